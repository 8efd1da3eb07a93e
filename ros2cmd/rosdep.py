"""`rosdep`, answered from this environment ("Managing Dependencies with rosdep", and every
package page's `rosdep install -i --from-path src --rosdistro jazzy -y`).

Nothing is installed here from apt, and there is no rosdistro database to download. So this
rosdep reads the packages' package.xml dependencies (catkin_pkg, as rosdep does, with their
conditions evaluated) and checks each key against this environment: a package in the ament
index (AMENT_PREFIX_PATH, then .venv), a `python3-*` key against the installed Python
distributions. All there: rosdep's own `#All required rosdeps installed successfully`, status
0. Otherwise rosdep's error, each missing key with how to get it here (a PyPI name, or that it
needs a ROS installation), status 1. It installs nothing.

    rosdep install -i --from-paths src --rosdistro jazzy -y
    rosdep check --from-paths src -i        rosdep keys --from-paths src -i
    rosdep init, rosdep update              one line each: nothing to set up or download here

Options as rosdep's (`--from-path` is its abbreviation): -i/--ignore-src, -y, -s, -r, -q,
--rosdistro, --skip-keys, -t/--dependency-types.
"""

from __future__ import annotations

import argparse
import os
import re
import shlex
import sys
from collections.abc import Collection, Sequence
from importlib import metadata

from catkin_pkg.package import InvalidPackage, parse_package
from catkin_pkg.packages import find_packages

from ros2cmd.errors import ToolError
from ros_tutorials_common import ament
from ros_tutorials_common.pypi_packages import PYPI_NAMES, not_available_line
from ros_tutorials_common.shutdown import program_main

DEPENDENCY_TYPES = ("build", "buildtool", "build_export", "buildtool_export", "exec", "test")
ALL_TYPES = (*DEPENDENCY_TYPES, "doc")
# rosdep keys whose Python distribution has another name than the key without `python3-`.
PYTHON_KEYS = {
    "python3-yaml": "PyYAML",
    "python3-catkin-pkg": "catkin_pkg",
    "python3-opencv": "opencv-python",
    "python3-serial": "pyserial",
    "python3-pil": "Pillow",
}
# ROS 2 keys that a package here stands for: ROS 2 has tf2_ros (C++, with tf2_echo ...) and
# tf2_ros_py (the Python module tf2_ros) apart; here the package tf2_ros is both.
PROVIDED_BY = {"tf2_ros_py": "tf2_ros"}
# A rosdep key is a name: a ROS package's, or one of rosdep's rules (Debian-like names such as
# libboost-dev, libstdc++-dev). Anything else (spaces, `;`, `$(...)`) is not looked up, and is
# shown quoted, never as part of a line to paste.
KEY_PATTERN = re.compile(r"[A-Za-z0-9][A-Za-z0-9._+-]*")
# System keys of rosdep's rules (ros/rosdistro rosdep/base.yaml) and the Debian packages they
# install on Ubuntu 24.04, ROS 2 Jazzy's platform (read 2026-11-28).
SYSTEM_KEYS = {
    "assimp": ("libassimp-dev",),
    "boost": ("libboost-all-dev",),
    "bullet": ("libbullet-dev",),
    "clang-format": ("clang-format",),
    "cmake": ("cmake",),
    "cppcheck": ("cppcheck",),
    "curl": ("libcurl4-openssl-dev", "curl"),
    "doxygen": ("doxygen",),
    "eigen": ("libeigen3-dev",),
    "ffmpeg": ("ffmpeg", "libavcodec-dev", "libavformat-dev", "libavutil-dev", "libswscale-dev"),
    "git": ("git",),
    "graphviz": ("graphviz",),
    "gtest": ("libgtest-dev",),
    "libpcl-all-dev": ("libpcl-dev",),
    "libqt5-core": ("libqt5core5t64",),
    "nlohmann-json-dev": ("nlohmann-json3-dev",),
    "openssl": ("openssl",),
    "pkg-config": ("pkg-config",),
    "sqlite3": ("sqlite3",),
    "tinyxml": ("libtinyxml-dev",),
    "tinyxml2": ("libtinyxml2-dev",),
    "uncrustify": ("uncrustify",),
    "wget": ("wget",),
    "yaml-cpp": ("libyaml-cpp-dev",),
    "zlib": ("zlib1g-dev",),
}
# rosdep's commands this rosdep has no answer for.
OTHER_COMMANDS = ("db", "resolve", "search", "what-needs", "where-defined", "fix-permissions")
# Test dependencies of every ament_cmake package `ros2 pkg create` makes, needed only with
# BUILD_TESTING on, which this environment's toolchain file leaves off (they are not on PyPI).
BUILD_TESTING_ONLY = ("ament_lint_auto", "ament_lint_common")
HERE = "rosdep answers from this environment (its ament index and Python packages)"
NOT_HERE = (
    "this rosdep answers from this environment (the ament index and the Python packages "
    "installed in it); it has no rosdep database"
)


class Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line, as every tool here
        sys.stderr.write(f"rosdep: error: {message}\n")
        sys.exit(2)


def parser() -> Parser:
    p = Parser(prog="rosdep", description=__doc__.split("\n")[0])
    p.add_argument("command", nargs="?", help="install, check, keys, init, update")
    p.add_argument("arguments", nargs="*", help="packages, or paths with --from-paths")
    p.add_argument("--from-paths", action="store_true", help="the arguments are paths")
    p.add_argument(
        "--ignore-packages-from-source",
        "--ignore-src",
        "-i",
        dest="ignore_src",
        action="store_true",
        help="skip keys that are packages in the paths",
    )
    p.add_argument("--rosdistro", help="the ROS distribution (this environment: jazzy)")
    p.add_argument("--default-yes", "-y", action="store_true", help="accepted (installs nothing)")
    p.add_argument("--simulate", "-s", action="store_true", help="do not print the success line")
    p.add_argument(
        "-r", dest="robust", action="store_true", help="continue despite keys not resolved"
    )
    p.add_argument("-q", dest="quiet", action="store_true", help="accepted")
    p.add_argument("--skip-keys", action="append", default=[], help="keys not to check")
    p.add_argument(
        "-t",
        "--dependency-types",
        action="append",
        default=[],
        choices=ALL_TYPES,
        help="the dependency types to check (default: all but doc)",
    )
    return p


def workspace_packages(paths: Sequence[str]) -> dict[str, object]:
    """The packages below PATHS (catkin_pkg, as rosdep finds them), by name."""
    found: dict[str, object] = {}
    for path in paths:
        if not os.path.exists(path):
            raise ToolError(f"given path '{path}' does not exist")
        try:
            for package in find_packages(path).values():
                found[package.name] = package
        except (InvalidPackage, RuntimeError) as error:
            raise ToolError(" ".join(str(error).split())) from None
    return found


def installed_packages(names: Sequence[str]) -> dict[str, object]:
    """The packages NAMES from the ament index, as `rosdep install PKG` takes them."""
    found = {}
    for name in names:
        try:
            found[name] = parse_package(str(ament.share_directory(name) / "package.xml"))
        except InvalidPackage as error:
            raise ToolError(" ".join(str(error).split())) from None
        except (ament.PackageNotFound, OSError):
            raise ToolError(
                f"no package '{name}' in the ament index (a folder of packages: --from-paths PATH)"
            ) from None
    return found


def keys(package: object, types: Sequence[str]) -> list[str]:
    """The package's rosdep keys of those dependency types, their conditions evaluated."""
    try:
        package.evaluate_conditions({**os.environ, "ROS_VERSION": "2", "ROS_PYTHON_VERSION": "3"})
    except ValueError as error:  # a condition="..." catkin_pkg cannot read
        raise ToolError(f"package {package.name}: {' '.join(str(error).split())}") from None
    names = []
    for kind in types:
        for depend in getattr(package, f"{kind}_depends"):
            if depend.evaluated_condition is not False and depend.name not in names:
                names.append(depend.name)
    return names


def python_installed(key: str) -> tuple[bool, str]:
    """Whether a python3-* key's distribution is installed, and its PyPI name."""
    name = PYTHON_KEYS.get(key, key.removeprefix("python3-"))
    try:
        metadata.distribution(name)
    except metadata.PackageNotFoundError:
        return False, name
    return True, name


def is_key(key: str) -> bool:
    """Whether KEY is a name rosdep could look up (KEY_PATTERN)."""
    return KEY_PATTERN.fullmatch(key) is not None


def shown(key: str) -> str:
    """KEY as printed: itself when it is a key, else its characters escaped (control
    characters, non-ASCII) and single-quoted as the shell quotes, so that it stays on its line
    and pasted runs nothing."""
    return key if is_key(key) else shlex.quote(key.encode("unicode_escape").decode("ascii"))


def missing_reason(key: str, index: Collection[str], workspace: Collection[str]) -> str | None:
    """None if KEY is here, else how to get it, in one line."""
    if not is_key(key):
        return (
            "not a rosdep key (a key is a package name: letters, digits and - _ . +); "
            "nothing to install for it"
        )
    if key in index or PROVIDED_BY.get(key) in index:
        return None
    if key in workspace:
        return (
            "a package of your workspace, not installed: add -i (--ignore-src) to leave it "
            "to colcon build"
        )
    if key.startswith("python3-"):
        installed, name = python_installed(key)
        return None if installed else f"pip install {shlex.quote(name)}"
    impossible = not_available_line(key)
    if impossible:
        return impossible
    if key in PYPI_NAMES:
        return f"pip install {shlex.quote(PYPI_NAMES[key])}"
    if key in SYSTEM_KEYS:
        debian = " ".join(shlex.quote(name) for name in SYSTEM_KEYS[key])
        return f"a system package, not a ROS one: sudo apt install {debian}"
    if not re.fullmatch(r"[a-z][a-z0-9_]*", key):  # not a ROS package name: a rule's key
        return (
            "a system package of rosdep's rules, not a ROS one: on Ubuntu, the Debian "
            "package its rule names (ros/rosdistro rosdep/base.yaml), installed with apt"
        )
    return (
        f"no package '{key}' in the ament index: if PyPI has it, pip install "
        f"ros-jazzy-{key.replace('_', '-')}; otherwise it needs a ROS installation"
    )


def ready_packages(
    selected: dict[str, object], missing: dict[str, list], types: Sequence[str]
) -> list[str]:
    """The packages whose keys are all here and whose workspace dependencies are ready too."""
    depends = {
        name: {key for key in keys(package, types) if key in selected and key != name}
        for name, package in selected.items()
    }
    ready: set[str] = set()
    changed = True
    while changed:
        changed = False
        for name in selected:
            if name not in ready and name not in missing and depends[name] <= ready:
                ready.add(name)
                changed = True
    return sorted(ready)


def check(args: argparse.Namespace) -> tuple[dict, dict, dict, list[str]]:
    """Each package's keys; per package its missing keys with how to get them; the
    BUILD_TESTING_ONLY keys it names that are not here; and the packages that are ready."""
    if not args.arguments:
        raise ToolError("no packages or stacks specified")
    if args.from_paths:
        selected = workspace_packages(args.arguments)
    else:
        selected = installed_packages(args.arguments)
    workspace = set(selected) if args.from_paths else set()
    skipped = {key for text in args.skip_keys for key in text.split()}
    if args.ignore_src:
        skipped |= workspace
    index = set(ament.packages())
    types = args.dependency_types or DEPENDENCY_TYPES
    all_keys: dict[str, list[str]] = {}
    missing: dict[str, list[tuple]] = {}
    untested: dict[str, list[str]] = {}
    for name, package in sorted(selected.items()):
        all_keys[name] = [key for key in keys(package, types) if key not in skipped]
        needed = set(keys(package, [t for t in types if t != "test"]))
        for key in all_keys[name]:
            reason = missing_reason(key, index, workspace)
            if reason and key in BUILD_TESTING_ONLY and key not in needed:
                untested.setdefault(name, []).append(key)
            elif reason:
                missing.setdefault(name, []).append((key, reason))
    return all_keys, missing, untested, ready_packages(selected, missing, types)


def run(args: argparse.Namespace) -> int:
    if args.command is None:
        raise ToolError("Please enter a command (install, check, keys, init, update)")
    if args.command == "init":
        print(f"rosdep init: nothing to set up here: {HERE}, without a sources list")
        return 0
    if args.command == "update":
        print(f"rosdep update: nothing to download here: {HERE}, without a rosdistro index")
        return 0
    if args.command in OTHER_COMMANDS:
        raise ToolError(f"rosdep {args.command} is not available here: {NOT_HERE}")
    if args.command not in ("install", "check", "keys"):
        raise ToolError(f"Unsupported command {args.command}.")
    if args.rosdistro not in (None, "jazzy"):
        raise ToolError(f"--rosdistro {args.rosdistro}: this environment is ROS 2 jazzy")
    all_keys, missing, untested, ready = check(args)
    if args.command == "keys":
        print("\n".join(sorted({shown(key) for found in all_keys.values() for key in found})))
        return 0
    for name, found in untested.items():
        print(
            f"note: {name}: {', '.join(found)} (test dependencies) are not on PyPI: "
            "`colcon build` here leaves BUILD_TESTING off and does not need them",
            file=sys.stderr,
        )
    if not missing:
        if args.command == "check":
            print("All system dependencies have been satisfied")
        elif not args.simulate:
            print("#All required rosdeps installed successfully")
        return 0
    print(
        "ERROR: the following packages/stacks could not have their rosdep keys resolved\n"
        "to system dependencies:",
        file=sys.stderr,
    )
    for name, found in missing.items():
        for key, reason in found:
            print(f"{name}: {shown(key)}: {reason}", file=sys.stderr)
    if ready:
        print(
            f"ready: every dependency of {', '.join(ready)} is here "
            f"(colcon build --packages-select {' '.join(ready)})",
            file=sys.stderr,
        )
    if args.command == "install" and args.robust:
        print("Continuing to install resolvable dependencies...")
        if not args.simulate:
            print("#All required rosdeps installed successfully")
        return 0
    return 1


@program_main
def main(argv: Sequence[str] | None = None) -> int:
    args = parser().parse_intermixed_args(argv)
    try:
        return run(args)
    except ToolError as error:
        print(f"{error.prefix}{error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
