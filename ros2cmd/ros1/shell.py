"""ROS 1's shell commands that no program can be here: each says what to type instead.

    roscd ros_tutorials_topic      error: roscd changes your shell's folder, which a program
                                   cannot do; type: cd /.../ros_tutorials_topic
    rosed PKG FILE                 the same for an editor: ${EDITOR:-nano} /.../FILE
    catkin_make                    `colcon build` in your workspace; `make interfaces` here
    catkin_create_pkg PKG DEPS     the `ros2 pkg create` line that makes PKG (rospy -> rclpy)
    catkin_init_workspace          ROS 2 workspaces need none: `mkdir -p ~/ros2_ws/src`
    roscp PKG FILE DEST            the `cp` to type
    rviz, rviz2                    a GUI tool this project does not have, and what does its job

ROS 1 made roscd and rosed shell functions (setup.bash); ROS 2 has neither. See the README's
"Coming from ROS 1".
"""

from __future__ import annotations

import argparse
import contextlib
import shlex
import sys
from collections.abc import Sequence
from pathlib import Path

from ros_tutorials_common import ament, completion, lesson_scripts, packages
from ros_tutorials_common.shutdown import program_main


def _folder(where: str) -> str:
    """The folder of PKG[/DIR], as roscd took it (LookupError, one line, if unknown). A DIR
    the package does not have here (seed 000's ros_tutorials_topic/src) is said and left out."""
    package, _, below = where.partition("/")
    folder = packages.package_folder(package)
    if below and not (folder / below).is_dir():
        return f"{shlex.quote(str(folder))} (it has no {below}/ here)"
    return shlex.quote(str(folder / below if below else folder))


def _complete_package(program: str, *more: str) -> None:
    """If the shell asks for TAB's completions, answer them (and end here): a package name
    first, as ROS 1's roscd, rosed and roscp completed it."""
    if completion.requested():
        parser = argparse.ArgumentParser(prog=program)
        for name in ("package", *more):
            parser.add_argument(name)
        completion.attach(parser, package=completion.package_names)
        completion.answer(parser)


def _args(argv: Sequence[str] | None) -> list[str]:
    return list(sys.argv[1:] if argv is None else argv)


def _say(message: str) -> int:
    print(f"error: {message}", file=sys.stderr)
    return 1  # it did not do what was typed


def _pointed(argv: Sequence[str] | None, count: int, usage: str, instead: str) -> int:
    """The line for a command whose first argument names a package's folder: ``instead``
    with {folder} and {args} filled in, or its usage, or the unknown package."""
    args = _args(argv)
    if len(args) != count:
        return _say(usage)
    try:
        folder = _folder(args[0])
    except LookupError as error:
        return _say(str(error))
    return _say(instead.format(folder=folder, args=args))


@program_main
def roscd(argv: Sequence[str] | None = None) -> int:
    _complete_package("roscd")
    return _pointed(
        argv,
        1,
        "usage: roscd PKG[/DIR]; here: cd $(rospack find PKG)/DIR",
        "roscd changes your shell's folder, which a program cannot do; type: cd {folder}",
    )


@program_main
def rosed(argv: Sequence[str] | None = None) -> int:
    """The editor line for FILE of PKG, found by name anywhere in the package, as ROS 1's rosed
    found it; a file of the book's C++ (service_client.cpp) is the lesson module that runs as
    the executable of its name here (client.py)."""
    _complete_package("rosed", "file")
    args = _args(argv)
    if len(args) != 2:
        return _say("usage: rosed PKG FILE; here: $EDITOR $(rospack find PKG)/FILE")
    package, name = args[0].partition("/")[0], args[1]
    try:
        folders = _package_folders(package)
    except LookupError as error:
        return _say(str(error))
    found = next((f for f in (_file_in(folder, name) for folder in folders) if f), None)
    if found is not None:
        return _say(f"rosed is a ROS 1 shell function; type: ${{EDITOR:-nano}} {_quoted(found)}")
    module = _executable_source(package, Path(name).stem)
    if module is not None:
        return _say(
            f"{package} has no {name} here; its node {Path(name).stem} is {module.name}: "
            f"type: ${{EDITOR:-nano}} {_quoted(module)}"
        )
    where = ", ".join(str(folder) for folder in folders)
    return _say(f"{package} has no file {name} here ({where})")


def _quoted(path: Path) -> str:
    return shlex.quote(str(path))


def _package_folders(package: str) -> list[Path]:
    """The package's folder; for a seed's name for several packages, each one's."""
    try:
        return [packages.package_folder(package)]
    except LookupError:
        folders = [packages.package_folder(p) for p in packages.resolve_package(package)]
        if not folders:
            raise
        return folders


def _executable_source(package: str, executable: str) -> Path | None:
    """The source file of the module that runs as EXECUTABLE of PACKAGE, if it is one."""
    try:
        line = packages.command(package, executable)
    except LookupError:
        return None
    if line[1:2] != ["-m"]:
        return None
    # A lesson starts as `python -m ros_tutorials_common.lesson_scripts PKG.MODULE ...`.
    started = line[3] if line[2] == lesson_scripts.THIS and len(line) > 3 else line[2]
    package_name, _, module = started.rpartition(".")
    folder = packages.package_dirs().get(package_name)
    source = folder / f"{module}.py" if folder else None
    return source if source is not None and source.is_file() else None


INTERFACE_KINDS = ("msg", "srv", "action")
OWN_INTERFACES = "ros_tutorials_interfaces"  # the seeds' .msg and .srv files are here


@program_main
def roscp(argv: Sequence[str] | None = None) -> int:
    """The `cp` of the file, as ROS 1's roscp found it by name in the package; a .msg, .srv
    or .action the package does not hold here is the interface package's that has it."""
    _complete_package("roscp", "file", "destination")
    args = _args(argv)
    if len(args) != 3:
        return _say("usage: roscp PKG FILE DEST; here: cp $(rospack find PKG)/FILE DEST")
    package, name, destination = args
    try:
        # A seed's name for several packages (rospy_tutorials): the file of any of them.
        folders = _package_folders(package)
    except LookupError as error:
        return _say(str(error))
    found = [_file_in(folder, name) for folder in folders]
    source = next((f for f in found if f is not None), None) or _interface_file(name)
    if source is None:
        where = ", ".join(str(folder) for folder in folders)
        return _say(f"{package} has no file {name} here ({where})")
    return _say(f"roscp is ROS 1's; type: cp {shlex.quote(str(source))} {shlex.quote(destination)}")


def _file_in(folder: Path, name: str) -> Path | None:
    if (folder / name).is_file():
        return folder / name
    found = sorted(p for p in folder.rglob(Path(name).name) if p.is_file())
    return found[0] if found else None


def _interface_file(name: str) -> Path | None:
    """NAME (AddTwoInts.srv) in an installed interface package: this project's first (its
    source folder, where a learner edits it), then the others by name."""
    kind = Path(name).suffix.lstrip(".")
    if kind not in INTERFACE_KINDS:
        return None
    owners = sorted(ament.resources("rosidl_interfaces"), key=lambda p: p != OWN_INTERFACES)
    for owner in owners:
        with contextlib.suppress(LookupError):
            folder = packages.package_folder(owner)
            if (folder / kind / Path(name).name).is_file():
                return folder / kind / Path(name).name
    return None


@program_main
def catkin_make(argv: Sequence[str] | None = None) -> int:
    return _say(
        "catkin_make is ROS 1's; in your workspace (~/ros2_ws) type: colcon build, then "
        "source install/setup.bash (this project's own interfaces/: run `make interfaces`)"
    )


# ROS 1 package dependencies and what a ROS 2 Python package depends on instead.
ROS2_DEPENDENCIES = {"rospy": "rclpy", "roscpp": "rclpy", "message_generation": "", "": ""}


@program_main
def catkin_create_pkg(argv: Sequence[str] | None = None) -> int:
    """Not catkin_pkg's tool (a catkin package that nothing here builds): the ROS 2 line."""
    args = [arg for arg in _args(argv) if not arg.startswith("-")]
    if not args:
        return _say(
            "catkin_create_pkg is ROS 1's; in ~/ros2_ws/src type: ros2 pkg create "
            "--build-type ament_python PKG --dependencies rclpy std_msgs"
        )
    dependencies = dict.fromkeys(ROS2_DEPENDENCIES.get(dep, dep) for dep in args[1:])
    dependencies.pop("", None)
    depends = f" --dependencies {' '.join(dependencies)}" if dependencies else ""
    return _say(
        "catkin_create_pkg is ROS 1's; in ~/ros2_ws/src type: ros2 pkg create "
        f"--build-type ament_python {shlex.quote(args[0])}{depends}"
    )


@program_main
def catkin_init_workspace(argv: Sequence[str] | None = None) -> int:
    return _say(
        "catkin_init_workspace is ROS 1's; a ROS 2 workspace needs no set-up: mkdir -p "
        "~/ros2_ws/src, create packages there, run colcon build in ~/ros2_ws"
    )


def roswtf(argv: Sequence[str] | None = None) -> int:
    return _say("roswtf is ROS 1's; here: ros2 doctor (or ros2 wtf), ros2 doctor --report")
