"""`rqt_console` (also `ros2 run rqt_console rqt_console`): the live /rosout in the terminal.

Every ROS 2 node sends its log lines to /rosout as rcl_interfaces/msg/Log (besides printing
them), as ROS 1 nodes did. This prints them one a line, time, level, node (the logger name,
as the nodes print it) and message, coloured by level when the output is a terminal, with
filters by level, node and text. /rosout is transient-local: each node keeps its last lines
(up to 1000, for 10 s) for subscribers that join later; ``--since SECONDS`` prints those of
them that are at most that old before the live ones.

    rqt_console --level warn --node /ns1/topic_publisher --text "msg = 1"
"""

from __future__ import annotations

import argparse
import fnmatch
import sys
import time
from collections.abc import Callable
from typing import Any

from rcl_interfaces.msg import Log
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

from ros2cmd.graph import Graph, until_stopped
from ros_tutorials_common.cli import positive_int, positive_seconds

LEVELS = {"debug": Log.DEBUG, "info": Log.INFO, "warn": Log.WARN, "error": Log.ERROR}
LEVELS["fatal"] = Log.FATAL
LEVEL_NAMES = {value: name.upper() for name, value in LEVELS.items()}
COLOURS = {  # ANSI: grey, default, yellow, red, bold red
    Log.DEBUG: "\033[90m",
    Log.INFO: "",
    Log.WARN: "\033[33m",
    Log.ERROR: "\033[31m",
    Log.FATAL: "\033[1;31m",
}
RESET = "\033[0m"
# As rcl publishes /rosout: reliable, transient-local, 1000 deep (we take what it keeps).
ROSOUT_QOS = QoSProfile(
    history=HistoryPolicy.KEEP_LAST,
    depth=1000,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)


def logger_name(node: str) -> str:
    """'/ns1/topic_publisher' -> 'ns1.topic_publisher', the node's logger name in ROS 2."""
    return node.strip("/").replace("/", ".")


def node_matcher(pattern: str) -> Callable[[str], bool]:
    """`--node /ns1/topic_publisher`, `ns1.topic_publisher` or `*publisher*`: which loggers."""
    wanted = logger_name(pattern)
    if any(c in wanted for c in "*?["):
        return lambda name: fnmatch.fnmatchcase(name, wanted)
    # A node's own logger, and its children (e.g. ns1.topic_publisher.rcl).
    return lambda name: name == wanted or name.startswith(wanted + ".")


def format_line(msg: Log, colour: bool) -> str:
    stamp = msg.stamp.sec + msg.stamp.nanosec * 1e-9
    clock = (
        time.strftime("%H:%M:%S", time.localtime(stamp)) + f".{msg.stamp.nanosec // 1000000:03d}"
    )
    level = LEVEL_NAMES.get(msg.level, str(msg.level))
    line = f"[{clock}] [{level}] [{msg.name}]: {msg.msg}"
    if colour and COLOURS.get(msg.level):
        return f"{COLOURS[msg.level]}{line}{RESET}"
    return line


class Filter:
    def __init__(self, level: str = "debug", node: str | None = None, text: str | None = None):
        self.level = LEVELS[level]
        self.node = node_matcher(node) if node else None
        self.text = text.lower() if text else None

    def __call__(self, msg: Log) -> bool:
        return (
            msg.level >= self.level
            and (self.node is None or self.node(msg.name))
            and (self.text is None or self.text in msg.msg.lower())
        )


def console(
    graph: Graph,
    keep: Filter,
    since: float | None = None,
    count: int | None = None,
    colour: bool | None = None,
) -> None:
    """Print /rosout lines that pass the filter until Ctrl-C (or `count` of them)."""
    if colour is None:
        colour = sys.stdout.isatty()
    with until_stopped():
        _console(graph, keep, since, count, colour)


def _console(graph: Graph, keep: Filter, since: float | None, count: int | None, colour: bool):
    # Lines stamped before this (the ones /rosout still holds) are shown only with --since.
    oldest = time.time() - (since or 0.0)
    received: list[Log] = []
    graph.node.create_subscription(Log, "/rosout", received.append, ROSOUT_QOS)
    printed = 0

    def show(batch: list[Log]) -> bool:
        nonlocal printed
        for msg in batch:
            if msg.stamp.sec + msg.stamp.nanosec * 1e-9 < oldest or not keep(msg):
                continue
            print(format_line(msg, colour), flush=True)
            printed += 1
            if printed == count:
                return True
        return False

    if since:
        # What the nodes still hold arrives in one burst per node: let all of them arrive
        # (discovery complete), then print it in time order.
        graph.settle()
        batch, received[:] = sorted(received, key=_stamp), []
        if show(batch):
            return
    while True:
        graph.spin_once(0.1)
        batch, received[:] = list(received), []
        if show(batch):
            return


def _stamp(msg: Log) -> tuple[int, int]:
    return (msg.stamp.sec, msg.stamp.nanosec)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "-l", "--level", choices=list(LEVELS), default="debug", help="the lowest level shown"
    )
    parser.add_argument("--node", help="only this node's lines (/ns1/talker, ns1.talker, *talk*)")
    parser.add_argument("--text", help="only lines that contain this text (any case)")
    parser.add_argument(
        "--since",
        type=positive_seconds,
        metavar="SECONDS",
        help="first the lines at most this old that /rosout still holds (10 s at most)",
    )
    parser.add_argument("-n", "--count", type=positive_int, help="exit after this many lines")
    parser.add_argument("--no-colour", action="store_true", help="no colours, even on a terminal")


def run(graph: Graph, args: Any) -> None:
    console(
        graph,
        Filter(args.level, args.node, args.text),
        args.since,
        args.count,
        False if args.no_colour else None,
    )
