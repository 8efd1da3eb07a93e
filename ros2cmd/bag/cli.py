"""`ros2 bag record|info|play` and ROS 1's `rosbag record|info|play`: one code, two spellings.

`ros2 bag ...` takes ros2 bag's options and prints `ros2 bag info`'s layout; `rosbag ...`
also takes ROS 1's short options (`-O`, `-r`, `-l`, `-s`, durations like `5m`) and prints
ROS 1's info fields.
"""

from __future__ import annotations

import argparse
import math
import signal
import sys
from collections.abc import Sequence
from typing import Any

from ros2cmd.bag import info as bag_info
from ros2cmd.errors import ToolError
from ros_tutorials_common.cli import positive_int, positive_rate, positive_seconds, stdout_closed

# record and play need rclpy (and ros2cmd.cli imports it); info does not, and starts faster
# without it: those are imported where they are used.

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


def _record_arguments(parser: argparse.ArgumentParser, ros1: bool) -> None:
    parser.add_argument("topics", nargs="*", metavar="TOPIC", help="topics to record")
    parser.add_argument("-a", "--all", action="store_true", help="all topics, also later ones")
    output = parser.add_mutually_exclusive_group()
    output.add_argument("-o", "--output", help="the bag's folder (default rosbag2_<date-time>)")
    if ros1:
        output.add_argument("-O", dest="output", help="the same as -o")
    parser.add_argument(
        "--duration", type=duration_seconds, help="stop after this long (seconds, or 30s, 5m, 2h)"
    )
    parser.add_argument("--max-messages", type=positive_int, help="stop after this many messages")
    parser.set_defaults(run=lambda graph, a: _record(graph, a, ros1))


def _record(graph: Any, args: argparse.Namespace, ros1: bool) -> None:
    from ros2cmd.bag.record import record

    if args.topics and args.all:
        raise ToolError("give topics or -a, not both")
    record(graph, args.topics, args.all, args.output, args.duration, args.max_messages, ros1)


def _play_arguments(parser: argparse.ArgumentParser, ros1: bool) -> None:
    parser.add_argument("bag", help="the bag's folder (or one .mcap file)")
    parser.add_argument("-r", "--rate", type=positive_rate, default=1.0, help="speed factor")
    parser.add_argument("-l", "--loop", action="store_true", help="play again and again")
    parser.add_argument("--topics", nargs="+", metavar="TOPIC", help="play only these")
    parser.add_argument(
        *(["-s"] if ros1 else []),
        "--start-offset",
        *(["--start"] if ros1 else []),
        dest="start_offset",
        type=offset_seconds,
        default=0.0,
        help="start this many seconds into the bag",
    )
    parser.add_argument(
        "-m",
        "--remap",
        nargs="+",
        default=[],
        metavar="FROM:=TO",
        help="publish a topic under another name",
    )
    parser.add_argument(
        "--wait-for-subscribers",
        action="store_true",
        help="wait (up to --timeout) for a subscriber on each topic before publishing",
    )
    parser.set_defaults(run=_play, offline=False)


def _play(graph: Any, args: argparse.Namespace) -> None:
    from ros2cmd.bag.play import PlayOptions, parse_remap, play
    from ros2cmd.graph import until_stopped

    remaps = dict(parse_remap(text) for text in args.remap)
    options = PlayOptions(
        rate=args.rate,
        loop=args.loop,
        topics=args.topics,
        start_offset=args.start_offset,
        remaps=remaps,
        wait_for_subscribers=args.wait_for_subscribers,
    )
    # SIGTERM like Ctrl-C: stop publishing, no traceback from a context shut down under us.
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    if args.loop:  # runs until Ctrl-C: that is its normal end
        with until_stopped():
            play(graph, args.bag, options)
        return
    play(graph, args.bag, options)


def _reindex(path: str) -> None:
    from ros2cmd.bag.storage import reindex

    bag = reindex(path)
    print(f"Reindexed {path}: {bag.message_count} messages, metadata.yaml rewritten")


def _info_arguments(parser: argparse.ArgumentParser, ros1: bool) -> None:
    parser.add_argument("bag", help="the bag's folder (or one .mcap file)")
    parser.set_defaults(run=lambda _graph, a: bag_info.print_info(a.bag, ros1), offline=True)


def _timeout_option() -> argparse.ArgumentParser:
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


def _add_commands(sub: argparse._SubParsersAction, ros1: bool) -> None:
    _record_arguments(sub.add_parser("record", help="record topics into a new bag"), ros1)
    _info_arguments(sub.add_parser("info", help="what a bag holds"), ros1)
    reindex = sub.add_parser(
        "reindex", help="give an unfinished recording its summary and metadata.yaml"
    )
    reindex.add_argument("bag", help="the bag's folder")
    reindex.set_defaults(run=lambda _graph, a: _reindex(a.bag), offline=True)
    play_parser = sub.add_parser(
        "play", parents=[_timeout_option()], help="publish a bag's messages"
    )
    _play_arguments(play_parser, ros1)


def register(verbs: argparse._SubParsersAction, _common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("bag", help="bags: record, info, play (rosbag2, MCAP storage)")
    _add_commands(parser.add_subparsers(dest="command", metavar="COMMAND", required=True), False)


def rosbag_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="rosbag", description="ROS 1's rosbag, on ROS 2 bags (see: ros2 bag)"
    )
    _add_commands(parser.add_subparsers(dest="command", metavar="COMMAND", required=True), True)
    return parser


def rosbag(argv: Sequence[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv[:1] in (["info"], ["reindex"]):  # offline: no rclpy to load
        return _offline_only(argv[0], argv[1:])
    from ros2cmd.cli import execute
    from ros2cmd.graph import DEFAULT_TIMEOUT

    args: Any = rosbag_parser().parse_args(argv)
    return execute(
        lambda graph: args.run(graph, args),
        offline=getattr(args, "offline", False),
        timeout=getattr(args, "timeout", DEFAULT_TIMEOUT),
        spin_time=getattr(args, "spin_time", None),
    )


def _offline_only(command: str, argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="rosbag")
    _add_commands(parser.add_subparsers(dest="command", required=True), True)
    args = parser.parse_args([command, *argv])
    try:
        args.run(None, args)
    except ToolError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    except BrokenPipeError:
        stdout_closed()
    return 0
