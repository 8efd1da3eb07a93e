"""This environment as an ament install prefix: AMENT_PREFIX_PATH, and the lookups that read it.

ROS 2 finds packages through the ament resource index. Each install prefix named in
AMENT_PREFIX_PATH holds share/ament_index/resource_index/<type>/<name> files: `packages/std_msgs`
says std_msgs is installed in that prefix, `rosidl_interfaces/std_msgs` lists its interface
files; a package's own files are in <prefix>/share/<package>/. The ROS 2 wheels install that
layout into this environment (sys.prefix), `make setup` adds this project's packages to it
(tools/build_interfaces.py, tools/register_packages.py). `source .venv/bin/activate` sets
AMENT_PREFIX_PATH to it, as a ROS installation's setup.bash does (tools/ros_environment.py),
and a colcon workspace's install/setup.bash puts its own prefixes in front; a program started
without either (`.venv/bin/ros2 ...`) has no AMENT_PREFIX_PATH at all.

So the tools do not depend on it: ``apply_ament_defaults()`` puts sys.prefix last in
AMENT_PREFIX_PATH unless it is already there, so this environment is the underlay every user
setting is laid over, as /opt/ros/jazzy is the underlay of a sourced workspace. The prefixes a
user names stay first and win (an overlay's package shadows this environment's). Every lookup
below applies it first, so nothing can look before it; children started later inherit it.
"""

from __future__ import annotations

import os
import sys
from collections.abc import MutableMapping
from pathlib import Path

import ament_index_python

from ros_tutorials_common.errors import ToolError

PREFIX_PATH = "AMENT_PREFIX_PATH"


class PackageNotFound(LookupError):
    """No package (or resource) of that name in the ament index; str() is one line."""


def apply_ament_defaults(env: MutableMapping[str, str] | None = None) -> MutableMapping[str, str]:
    """Add this environment's prefix after the prefixes the user has set; return the environment."""
    if env is None:
        env = os.environ
    prefixes = [path for path in env.get(PREFIX_PATH, "").split(os.pathsep) if path]
    here = os.path.realpath(sys.prefix)
    if not any(os.path.realpath(path) == here for path in prefixes):
        prefixes.append(sys.prefix)
    env[PREFIX_PATH] = os.pathsep.join(prefixes)
    return env


def packages() -> dict[str, Path]:
    """Every package in the index and its install prefix (the first prefix that has it)."""
    return resources("packages")


def resources(resource_type: str) -> dict[str, Path]:
    """The resources of one type ('packages', 'rosidl_interfaces', ...) and their prefixes."""
    apply_ament_defaults()
    found = ament_index_python.get_resources(resource_type)
    return {name: Path(prefix) for name, prefix in sorted(found.items())}


def resource(resource_type: str, name: str) -> str:
    """The content of one resource, from the first prefix that has it."""
    apply_ament_defaults()
    try:
        content, _prefix = ament_index_python.get_resource(resource_type, name)
    except (LookupError, ValueError):  # ValueError: a name with '/' in it
        raise PackageNotFound(f"no {resource_type} resource {name!r} in the ament index") from None
    return content


def package_prefix(package: str) -> Path:
    """The install prefix of a package (what `ros2 pkg prefix` prints)."""
    apply_ament_defaults()
    try:
        return Path(ament_index_python.get_package_prefix(package))
    except (LookupError, ValueError):  # ValueError: not a valid package name
        raise PackageNotFound(f"no package {package!r} in the ament index") from None


def share_directory(package: str) -> Path:
    """<prefix>/share/<package>, where a package installs its files (package.xml, msg/, launch/)."""
    return package_prefix(package) / "share" / package


def definition_path(package: str, kind: str, base: str) -> Path:
    """The .msg, .srv or .action file of an interface, from its package's share folder."""
    try:
        path = share_directory(package) / kind / f"{base}.{kind}"
    except LookupError:
        path = None
    if path is None or not path.is_file():
        raise ToolError(f"no definition file for {package}/{kind}/{base}")
    return path
