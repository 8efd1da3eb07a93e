"""What both spellings of the bag commands share: `ros2 bag ...` (ros2/) and ROS 1's
`rosbag ...` (ros2cmd/ros1/rosbag.py) take the same durations, offsets and this project's own
options, run play the same way, and have the same `reindex`.

record and play need rclpy; info and reindex do not, and start faster without it: what needs
rclpy is imported where it is used.
"""

from __future__ import annotations

import argparse
import math
from typing import Any

from ros_tutorials_common.cli import positive_int, positive_seconds
from ros_tutorials_common.shutdown import terminate_as_ctrl_c

UNITS = {"s": 1.0, "m": 60.0, "h": 3600.0}


def duration_seconds(text: str) -> float:
    """A recording duration: seconds, or ROS 1's 30s / 5m / 2h; finite and above 0."""
    number, factor = text.strip(), 1.0
    if number and number[-1] in UNITS:
        number, factor = number[:-1], UNITS[number[-1]]
    try:
        value = float(number) * factor
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"{text!r} is not a positive duration (e.g. 30, 5m)")
    return value


def offset_seconds(text: str) -> float:
    """--start-offset: a finite number of seconds, 0 or more."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value >= 0):
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of seconds >= 0")
    return value


def limit_arguments(parser: argparse.ArgumentParser) -> None:
    """This project's own stops, in both spellings (rosbag2 has neither)."""
    parser.add_argument(
        "--duration", type=duration_seconds, help="stop after this long (seconds, or 30s, 5m, 2h)"
    )
    parser.add_argument("--max-messages", type=positive_int, help="stop after this many messages")


def remap_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "-m",
        "--remap",
        nargs="+",
        default=[],
        metavar="FROM:=TO",
        help="publish a topic under another name",
    )


def wait_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--wait-for-subscribers",
        action="store_true",
        help="wait (up to --timeout) for a subscriber on each topic before publishing",
    )


def remaps(rules: list[str]) -> dict[str, str]:
    from ros2cmd.bag.play import parse_remap

    return dict(parse_remap(text) for text in rules)


def run_play(graph: Any, bag: str, options: Any) -> None:
    from ros2cmd.bag.play import play
    from ros2cmd.graph import until_stopped

    # SIGTERM like Ctrl-C: stop publishing, no traceback from a context shut down under us.
    terminate_as_ctrl_c()
    if options.loop and options.ros1:  # runs until Ctrl-C: that is its normal end
        with until_stopped():
            play(graph, bag, options)
        return
    play(graph, bag, options)


def _reindex(path: str) -> None:
    from rosbag2.reindex import reindex

    bag = reindex(path)
    print(f"Reindexed {path}: {bag.message_count} messages, metadata.yaml rewritten")


def timeout_option() -> argparse.ArgumentParser:
    """play's --timeout (for --wait-for-subscribers); the other graph options mean nothing here."""
    from ros2cmd.graph import DEFAULT_TIMEOUT

    option = argparse.ArgumentParser(add_help=False)
    option.add_argument(
        "--timeout",
        type=positive_seconds,
        default=DEFAULT_TIMEOUT,
        help=f"seconds --wait-for-subscribers waits (default {DEFAULT_TIMEOUT:g})",
    )
    return option


def add_reindex(sub: argparse._SubParsersAction) -> None:
    reindex = sub.add_parser(
        "reindex", help="give an unfinished recording its summary and metadata.yaml"
    )
    reindex.add_argument("bag", help="the bag's folder")
    reindex.set_defaults(run=lambda _graph, a: _reindex(a.bag), offline=True)
