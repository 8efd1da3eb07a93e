"""colcon's package selection `needs_ros_installation`: in a workspace of several packages, a
package that cannot build here is left out with a one-line note, so that the others build.

A package whose build dependencies include one that only a ROS installation has (rclcpp, tf2:
pypi_packages.py) fails at its `find_package()`, and colcon then stops every other package of
the build ("Creating a workspace" clones ros/ros_tutorials, whose turtlesim is C++, beside a
learner's Python packages: `0 packages finished`). Such a package is still built when it is
named (`colcon build --packages-select cpp_pubsub`, `--packages-up-to`), or when nothing else
would be built: then colcon's one-line error (colcon_events.py) says why it fails. Only
`colcon build` and `colcon test` leave it out; `colcon list` lists every package.
The extension is registered in pyproject.toml (entry point group colcon_core.package_selection).
"""

from __future__ import annotations

import sys
from typing import Any

from colcon_core.package_selection import PackageSelectionExtensionPoint
from colcon_core.plugin_system import satisfies_version

from ros_tutorials_common.pypi_packages import not_available_line

VERBS = ("build", "test")


def unbuildable_reason(descriptor: Any) -> str | None:
    """Why the package cannot build here (its first such build dependency), else None."""
    for dependency in sorted(str(d) for d in descriptor.dependencies.get("build", ())):
        line = not_available_line(dependency)
        if line:
            return line
    return None


class NeedsRosInstallationSelection(PackageSelectionExtensionPoint):
    """Leave out, with a note, the packages that cannot build without a ROS installation."""

    # After the selections of colcon-package-selection (higher priorities run first).
    PRIORITY = 10

    def __init__(self) -> None:
        super().__init__()
        satisfies_version(PackageSelectionExtensionPoint.EXTENSION_POINT_VERSION, "^1.0")

    def select_packages(self, *, args: Any, decorators: list) -> None:
        if getattr(args, "verb_name", None) not in VERBS:
            return
        named = set(getattr(args, "packages_select", None) or ())
        named |= set(getattr(args, "packages_up_to", None) or ())
        left_out = {}
        for decorator in decorators:
            name = decorator.descriptor.name
            if decorator.selected and name not in named:
                reason = unbuildable_reason(decorator.descriptor)
                if reason:
                    left_out[name] = (decorator, reason)
        others = [d for d in decorators if d.selected and d.descriptor.name not in left_out]
        if not others:  # nothing else to build: colcon tries, and its error says why
            return
        for name, (decorator, reason) in left_out.items():
            decorator.selected = False
            print(
                f"note: {name} is left out: {reason} (`colcon {args.verb_name} "
                f"--packages-select {name}` tries it)",
                file=sys.stderr,
            )
