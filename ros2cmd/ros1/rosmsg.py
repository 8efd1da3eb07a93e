"""`rosmsg` and `rossrv` (show|list|package|packages): ROS 1's on `ros2 interface`'s code.

    rosmsg show turtlesim/Pose              ROS 1's pkg/Name: the tool says msg or srv
    rosservice type /spawn | rossrv show    the type read from a pipe, as ROS 1 did

Each command runs ros2cmd/interface/api.py's function, for one kind of type: msg or srv.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from ros2cmd import completion
from ros2cmd.interface import api as interface
from ros2cmd.ros1 import tool
from ros2cmd.typenames import KIND_NAMES
from ros_tutorials_common.shutdown import program_main


def _interface_parser(name: str, kind: str) -> argparse.ArgumentParser:
    what = KIND_NAMES[kind]
    parser, sub, _common = tool.new_parser(name, f"ROS 1's {name}, on ROS 2 (ros2 interface)")

    show = sub.add_parser("show", help=f"a {what}")
    show.add_argument("type", nargs="?", help="pkg/Name, Name, or - to read it from stdin")
    completion.attach(show, type=completion.interface_types((kind,), ros1=True))
    show.set_defaults(offline=True, run=lambda _, a: _show(_type_or_stdin(a.type, show), kind))

    p = sub.add_parser("list", help=f"all {what} types")
    p.set_defaults(offline=True, run=lambda _, a: print(*interface.list_types((kind,)), sep="\n"))

    p = sub.add_parser("package", help=f"the {what} types of a package")
    p.add_argument("package")
    completion.attach(p, package=completion.interface_packages)
    p.set_defaults(
        offline=True, run=lambda _, a: print(*interface.list_types((kind,), a.package), sep="\n")
    )

    p = sub.add_parser("packages", help=f"packages with {what} types")
    p.set_defaults(offline=True, run=lambda _, a: print(*interface.packages((kind,)), sep="\n"))
    tool.no_ros2_meaning(name, sub)
    return parser


def _type_or_stdin(type_name: str | None, parser: argparse.ArgumentParser) -> str:
    """No type given: read it from a pipe (`rosservice type /srv | rossrv show`), as ROS 1
    did; from a terminal that would only sit and wait, so say what is missing instead."""
    if type_name is not None:
        return type_name
    if sys.stdin.isatty():
        parser.error("the following arguments are required: type (or - to read it from stdin)")
    return "-"


def _show(type_name: str, kind: str) -> None:
    type_name = interface.type_name_argument(type_name)
    if type_name.count("/") == 1:  # ROS 1's pkg/Name: this tool says which kind
        package, base = type_name.split("/")
        type_name = f"{package}/{kind}/{base}"
    interface.show(type_name, ros1_style=True, kinds=(kind,))


@program_main  # the console script's entry
def rosmsg(argv: Sequence[str] | None = None) -> int:
    return tool.run(_interface_parser("rosmsg", "msg"), argv)


@program_main  # the console script's entry
def rossrv(argv: Sequence[str] | None = None) -> int:
    return tool.run(_interface_parser("rossrv", "srv"), argv)
