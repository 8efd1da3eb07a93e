"""The tutorial packages as the launcher sees them: where they are, what they can run.

A package is an importable ``ros_tutorials_*`` package. Its executables are found, never
listed by hand, so a lesson merged later is picked up with no change here:
- each module of the package that defines a top-level ``main()`` (``publisher``), and
- each console script whose entry point lives in the package (``topic_publisher``).
Both run as ``python -m <module>``; this is the one place that decides that.
"""

from __future__ import annotations

import ast
import importlib.metadata
import importlib.util
import pkgutil
import sys
from functools import cache
from pathlib import Path

PACKAGE_PREFIX = "ros_tutorials_"
# ROS package names whose executables live in a tutorial package of another name: turtlesim's
# nodes are in ros_tutorials_turtlesim, since rosidl's generated module is already `turtlesim`.
PACKAGE_ALIASES = {"turtlesim": "ros_tutorials_turtlesim"}


def real_name(package: str) -> str:
    """The tutorial package a ROS package name stands for (itself unless aliased)."""
    return PACKAGE_ALIASES.get(package, package)


@cache
def package_dirs() -> dict[str, Path]:
    """Every importable tutorial package and its directory."""
    found = {}
    for module in pkgutil.iter_modules():
        if module.ispkg and module.name.startswith(PACKAGE_PREFIX):
            spec = importlib.util.find_spec(module.name)
            if spec and spec.submodule_search_locations:
                found[module.name] = Path(next(iter(spec.submodule_search_locations)))
    return dict(sorted(found.items()))


def _has_main(source_file: Path) -> bool:
    # Read the source instead of importing it: importing a node module loads rclpy.
    try:
        tree = ast.parse(source_file.read_text(encoding="utf-8"))
    except (OSError, SyntaxError, UnicodeDecodeError):
        return False
    return any(isinstance(node, ast.FunctionDef) and node.name == "main" for node in tree.body)


@cache
def executables(package: str) -> dict[str, list[str]]:
    """Executable name -> command line, for one tutorial package ({} if unknown)."""
    package = real_name(package)
    directory = package_dirs().get(package)
    if directory is None:
        return {}
    found = {}
    for module in pkgutil.iter_modules([str(directory)]):
        if not module.ispkg and _has_main(directory / f"{module.name}.py"):
            found[module.name] = [sys.executable, "-m", f"{package}.{module.name}"]
    for script in importlib.metadata.entry_points(group="console_scripts"):
        module, _, function = script.value.partition(":")
        if module.startswith(f"{package}."):
            if function.strip() == "main":
                found[script.name] = [sys.executable, "-m", module]
            else:
                code = f"import sys; from {module} import {function}; sys.exit({function}())"
                found[script.name] = [sys.executable, "-c", code]
    return dict(sorted(found.items()))


def runnable_packages() -> list[str]:
    return [package for package in package_dirs() if executables(package)]


def launch_files(package: str) -> list[Path]:
    """The launch files a package ships in its ``launch/`` folder."""
    folder = package_dirs()[real_name(package)] / "launch"
    if not folder.is_dir():
        return []
    return sorted(path for path in folder.iterdir() if path.name.endswith((".launch", ".xml")))
