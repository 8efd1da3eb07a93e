"""What `ros2 pkg`'s sub-verbs share: a package's prefix and its executables.

The packages are those of the ament index (ros_tutorials_common/ament.py: this environment,
and what AMENT_PREFIX_PATH adds). A package's executables are exactly what `ros2 run` starts,
from the one table in ros_tutorials_common/packages.py: what an installed package has in
<prefix>/lib/<package>/, and for this project's packages and the seeds' names for them
(`demo_nodes_cpp`, `pub_sub`) the lessons: `turtlesim` is the interface package, its nodes are
ros_tutorials_turtlesim's, listed under the name the tutorials type.
"""

from __future__ import annotations

from pathlib import Path

from ros2cmd.errors import ToolError
from ros_tutorials_common import ament, packages


def package_prefix(name: str) -> Path:
    try:
        return ament.package_prefix(name)
    except ament.PackageNotFound:
        raise ToolError(f"Package '{name}' not found") from None


def executables(name: str) -> dict[str, Path]:
    """A package's executables: name -> the file that runs (a script or a module's source);
    the pairs `ros2 run` takes (ros_tutorials_common/packages.py), a seed's name's too."""
    found = packages.executable_files(name)
    if not found:
        package_prefix(name)  # "Package 'NAME' not found" unless it is a package
    return found
