"""What the ROS 1 graph tools (rostopic, rosservice, rosparam, rosnode, rosmsg, rossrv) share.

Each tool is a parser whose commands call the ros2 verbs' functions, built as the ros2 verbs
build theirs (topic.register, ...): one sub-parser per command, its `run` a default, run by
ros2cmd.cli like any ros2 command. Two ROS 1 habits are kept: options anywhere on the line, and
field values by position (``rosservice call /srv 10 5``). A command with no ROS 2 meaning
(``rosnode kill``, ``rosservice uri``, ...) says so in one line and names the ROS 2 way.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence
from typing import Any

from ros2cmd import completion
from ros2cmd.cli import common_options, run_parsed
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph
from ros2cmd.messages import parse_yaml

# ROS 1 commands that have no ROS 2 counterpart, and what to do instead.
NO_ROS2_MEANING = {
    ("rosnode", "kill"): "ROS 2 has no master to kill nodes through; stop the node's process "
    "(Ctrl-C in its terminal or the launcher's, or `kill PID`)",
    ("rosnode", "ping"): "ROS 2 nodes have no XML-RPC address to ping; `rosnode info NODE` "
    "shows whether the node is in the graph",
    ("rosnode", "machine"): "ROS 2 does not record which machine a node runs on; "
    "`rosnode list` (or `ros2 node list`) shows every node in the graph",
    ("rosnode", "cleanup"): "ROS 2 has no master registry to clean; DDS drops vanished nodes "
    "by itself, and `rosnode list` shows the ones still there",
    ("rosservice", "uri"): "ROS 2 services have no ROSRPC URI (they travel over DDS); "
    "`rosservice info SERVICE` shows the node that serves it and its type",
    ("rosparam", "delete"): "a ROS 2 parameter belongs to its node and stays declared; set "
    "another value with `rosparam set`",
    ("rosmsg", "md5"): "ROS 2 types have no MD5 sum; `rosmsg show` gives the definition",
    ("rossrv", "md5"): "ROS 2 types have no MD5 sum; `rossrv show` gives the definition",
    ("rosmsg", "users"): "ROS 2 keeps no index of the code that uses a type; "
    "`rostopic find TYPE` (or `ros2 topic find TYPE`) lists the topics that carry it",
    ("rossrv", "users"): "ROS 2 keeps no index of the code that uses a type; "
    "`rosservice find TYPE` (or `ros2 service find TYPE`) lists the services that use it",
}


def values_from_args(args: Sequence[str]) -> Any:
    """ROS 1 values: one YAML mapping (`'{a: 1}'`), or field values in order (`10 5`)."""
    # An empty argument ("" in the shell) is an empty string, as in ROS 1
    # (`rosservice call /spawn 3 3 0.2 ""` lets turtlesim pick the name), not YAML's null.
    values = [parse_yaml(arg) if arg else "" for arg in args]
    if not values:
        return None
    if len(values) == 1 and isinstance(values[0], dict):
        return values[0]
    return values


def new_parser(tool: str, description: str) -> tuple[argparse.ArgumentParser, Any, Any]:
    parser = argparse.ArgumentParser(prog=tool, description=description)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    parser.set_defaults(commands=sub.choices)  # for run()
    return parser, sub, common_options()


def no_ros2_meaning(tool: str, sub: Any) -> None:
    for (owner, command), reason in NO_ROS2_MEANING.items():
        if owner == tool:
            p = sub.add_parser(command, help="(no ROS 2 counterpart)")
            p.add_argument("rest", nargs="*")
            p.set_defaults(offline=True, run=_refuse(f"{tool} {command}", reason))


def _refuse(command: str, reason: str) -> Callable:
    def run(_graph: Graph | None, _args: argparse.Namespace) -> None:
        raise ToolError(f"`{command}` has no ROS 2 meaning: {reason}")

    return run


def run(parser: argparse.ArgumentParser, argv: Sequence[str] | None) -> int:
    # ROS 1 put options anywhere: `rostopic pub /cmd_vel -r 10 geometry_msgs/Twist '...'`.
    # argparse can parse that only below the command (not through subparsers), so pick it.
    completion.answer(parser)  # the shell asking for TAB's completions: answered, ends here
    argv = sys.argv[1:] if argv is None else list(argv)
    commands = parser.get_default("commands")
    if argv and argv[0] in commands:
        args = commands[argv[0]].parse_intermixed_args(argv[1:])
    else:
        args = parser.parse_args(argv)  # help, or a usage error
    return run_parsed(args)
