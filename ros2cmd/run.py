"""`ros2 run [--prefix PREFIX] PKG EXECUTABLE [ARGS]`, and what rosrun runs through it.

PKG and EXECUTABLE are looked up in the package index (ros_tutorials_common/packages.py, the one
place that turns them into a command line); ROS 1's argument forms (`__name:=NAME`,
`_param:=value`, `from:=to`) become one `--ros-args` block, checked here so that a bad name is
one line before the node starts; the process is replaced by the executable, with this
project's DDS defaults. ROS 1's spelling, `rosrun`, is ros2cmd/ros1/rosrun.py.
"""

from __future__ import annotations

import argparse
import os
import re
import shlex
import sys
from collections.abc import Sequence

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.sub_verbs import VERB_HELP
from ros_tutorials_common import names, packages
from ros_tutorials_common.dds import apply_dds_defaults, environment_problem

# ROS 1 special keys with no ROS 2 meaning, and what to do instead.
NO_ROS2_MEANING = {
    "__master": "ROS 2 has no master; nodes find each other by DDS discovery "
    "(same ROS_DOMAIN_ID, see `roscore`)",
    "__ip": "ROS 2 has no XML-RPC address; DDS picks the network interfaces",
    "__hostname": "ROS 2 has no XML-RPC address; DDS picks the network interfaces",
    "__log": "ROS 2 names its log files itself; set ROS_LOG_DIR for the folder",
}


_TOKEN, _RULE = names.TOKEN, names.RULE  # a part of a ROS name, as ROS 1 and ROS 2 allow it


def _check(arg: str, value: str, what: str, pattern: str, parts: str = "") -> str:
    """value if it matches; else ToolError naming the argument, the bad name and the rule
    (so that rcl never prints its own "Couldn't parse remap rule ... lexeme")."""
    if not re.fullmatch(pattern, value):
        shown = f"'{value}'" if value else "an empty name"
        raise ToolError(f"{arg}: {shown} is not a valid {what} ({parts}{_RULE})")
    return value


def ros1_argument(arg: str) -> list[str] | None:
    """The ROS 2 rule for one ROS 1 `name:=value` argument; None if it is not one.

    The names are checked here: a bad one is one line (ToolError) before the node starts.
    """
    name, colon_equals, value = arg.partition(":=")
    if not colon_equals or not name or "=" in name or name.startswith("-"):
        return None  # not a ROS 1 argument: the program's own
    if name == "__name":
        return ["-r", f"__node:={_check(arg, value, 'node name', _TOKEN)}"]
    if name == "__ns":
        # ROS 1 took a relative namespace (`__ns:=r1`) as global; ROS 2 wants the '/'.
        namespace = "/" + value.strip("/")
        parts = "names separated by '/', each of "
        _check(arg, namespace, "namespace", f"/|(/{_TOKEN})+", parts)
        return ["-r", f"__ns:={namespace}"]
    if name in NO_ROS2_MEANING:
        raise ToolError(f"{arg}: {NO_ROS2_MEANING[name]}")
    if name.startswith("__"):
        raise ToolError(f"{arg}: unknown special argument (ROS 1 knew __name, __ns, __log, ...)")
    if name.startswith("_"):
        param = name[1:].replace("/", ".")
        parts = "parts separated by '.', each of "
        _check(arg, param, "parameter name", rf"{_TOKEN}(\.{_TOKEN})*", parts)
        return ["-p", f"{param}:={value}"]
    # ROS 1's private `~name` is ROS 2's `~/name`.
    source, target = (re.sub(r"^~(?=[^/])", "~/", side) for side in (name, value))
    for side, which in ((source, "from"), (target, "to")):
        if not names.valid_remap_name(side, which):  # the launcher's check, rcl's rules
            shown = f"'{side}'" if side else "an empty name"
            raise ToolError(
                f"{arg}: {shown} is not a valid topic or service name "
                f"(parts separated by '/', each of {_RULE})"
            )
    return ["-r", f"{source}:={target}"]


def translate_arguments(args: Sequence[str]) -> list[str]:
    """The program's arguments with the ROS 1 forms turned into one `--ros-args` block."""
    out: list[str] = []
    rules: list[str] = []
    in_ros_args = False
    for arg in args:
        if in_ros_args:
            out.append(arg)
            in_ros_args = arg != "--"
        elif arg == "--ros-args":
            out.append(arg)
            in_ros_args = True
        elif arg.startswith("--ros-arg") or arg in ("--ros_args", "-ros-args", "--rosargs"):
            # rcl would take what follows as the program's own arguments, and fail on them.
            raise ToolError(f"{arg}: did you mean --ros-args?")
        else:
            rule = ros1_argument(arg)
            if rule is None:
                out.append(arg)
            else:
                rules += rule
    if rules:
        # Inside an open --ros-args block the rules can simply follow.
        out += rules if in_ros_args else ["--ros-args", *rules]
    return out


def check_ros_arguments(args: Sequence[str]) -> None:
    """ToolError (one line) if rcl cannot parse the ROS arguments: a node, plain rclpy, would
    end in rclpy.init's traceback."""
    if "--ros-args" not in args:
        return
    from rclpy.utilities import remove_ros_args  # only here: rclpy takes a moment to load

    from ros_tutorials_common.ros import RCLError

    try:
        remove_ros_args(["node", *args])
    except RCLError as error:
        reason = str(error).split(", at ")[0]  # rcl appends its source file and line
        reason = reason.removeprefix("Failed to parse ROS arguments: ")
        raise ToolError(f"invalid ROS arguments: {reason}") from None


def command_line(package: str, executable: str, args: Sequence[str]) -> list[str]:
    """The full command line rosrun runs; ToolError if the names or arguments are wrong."""
    try:
        command = packages.command(package, executable)
    except packages.UnknownExecutable as error:
        raise ToolError(str(error)) from None
    arguments = translate_arguments(args)
    check_ros_arguments(arguments)
    return [*command, *arguments]


def ros2_command_line(package: str, executable: str, args: Sequence[str]) -> list[str]:
    """command_line(), with ros2run's wording when a name is unknown."""
    try:
        packages.command(package, executable)
    except packages.PackageNotFound as error:
        if packages.unsourced_install(package):
            raise ToolError(f"Package '{package}' not found: {error}") from None
        raise ToolError(f"Package '{package}' not found ({error})") from None
    except packages.UnknownExecutable as error:
        raise ToolError(f"No executable found ({error})") from None
    return command_line(package, executable, args)


def run(package: str, executable: str, args: Sequence[str], prefix: str | None = None) -> None:
    """Replace this process by the executable, started through PREFIX (a command line such
    as 'gdb -ex run --args') if given. Returns only by raising ToolError."""
    command = command_line(package, executable, args)
    _exec(command, shlex.split(prefix) if prefix else [])


def _exec(command: list[str], prefix: list[str]) -> None:
    # Any executable, a learner's own plain rclpy node too, starts with the project's DDS
    # defaults, and not at all with a ROS_DOMAIN_ID rcl would fail on (one line instead).
    problem = environment_problem()
    if problem:
        raise ToolError(problem)
    apply_dds_defaults()
    command = [*prefix, *command]
    sys.stdout.flush()
    sys.stderr.flush()
    try:
        os.execvp(command[0], command)
    except OSError as error:
        raise ToolError(f"cannot run {command[0]}: {error.strerror}") from None


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    """`ros2 run [--prefix PREFIX] package_name executable_name ...`, as ros2run has it."""
    parser = verbs.add_parser(
        "run",
        help=VERB_HELP["run"],
        description="Run a package specific executable",
    )
    parser.add_argument(
        "--prefix",
        help="Prefix command, which should go before the executable. Command must be wrapped "
        "in quotes if it contains spaces (e.g. --prefix 'gdb -ex run --args').",
    )
    parser.add_argument("package_name", help="Name of the ROS package")
    parser.add_argument("executable_name", help="Name of the executable")
    completion.attach(
        parser, package_name=completion.package_names, executable_name=completion.executable_names
    )
    parser.add_argument(
        "argv", nargs=argparse.REMAINDER, help="Pass arbitrary arguments to the executable"
    )
    parser.set_defaults(offline=True, run=_ros2_run)


def _ros2_run(_graph: object, args: argparse.Namespace) -> None:
    command = ros2_command_line(args.package_name, args.executable_name, args.argv)
    prefix = shlex.split(args.prefix) if args.prefix is not None else []
    if args.prefix is not None and not prefix:
        raise ToolError("--prefix: an empty command")
    _exec(command, prefix)
