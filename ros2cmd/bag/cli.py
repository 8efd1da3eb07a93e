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
from ros_tutorials_common.ctrl_c import exits_130_on_ctrl_c

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


# ROS 1's spelling: `rosbag record|play` (seed 004), ROS 1's options on the same code.


def _ros1_record_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topics", nargs="*", metavar="TOPIC", help="topics to record")
    parser.add_argument("-a", "--all", action="store_true", help="all topics, also later ones")
    output = parser.add_mutually_exclusive_group()
    output.add_argument("-o", "--output", help="the bag's folder (default rosbag2_<date-time>)")
    output.add_argument("-O", dest="output", help="the same as -o")
    _limit_arguments(parser)
    parser.set_defaults(run=_ros1_record)


def _limit_arguments(parser: argparse.ArgumentParser) -> None:
    """This project's own stops, in both spellings (rosbag2 has neither)."""
    parser.add_argument(
        "--duration", type=duration_seconds, help="stop after this long (seconds, or 30s, 5m, 2h)"
    )
    parser.add_argument("--max-messages", type=positive_int, help="stop after this many messages")


def _ros1_record(graph: Any, args: argparse.Namespace) -> None:
    from ros2cmd.bag.record import RecordOptions, record

    if args.topics and args.all:
        raise ToolError("give topics or -a, not both")
    if not args.topics and not args.all:
        raise ToolError("name the topics to record, or give -a for all of them")
    options = RecordOptions(
        topics=args.topics,
        all_topics=args.all,
        include_hidden_topics=bool(args.topics),  # a topic named is recorded, hidden or not
        duration=args.duration,
        max_messages=args.max_messages,
        keyboard=False,
        ros1=True,
    )
    record(graph, options, args.output)


def _ros1_play_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("bag", help="the bag's folder (or one .mcap file)")
    parser.add_argument("-r", "--rate", type=positive_rate, default=1.0, help="speed factor")
    parser.add_argument("-l", "--loop", action="store_true", help="play again and again")
    parser.add_argument("--topics", nargs="+", metavar="TOPIC", help="play only these")
    parser.add_argument(
        "-s",
        "--start-offset",
        "--start",
        dest="start_offset",
        type=offset_seconds,
        default=0.0,
        help="start this many seconds into the bag",
    )
    _remap_argument(parser)
    _wait_argument(parser)
    parser.set_defaults(run=_ros1_play, offline=False)


def _remap_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "-m",
        "--remap",
        nargs="+",
        default=[],
        metavar="FROM:=TO",
        help="publish a topic under another name",
    )


def _wait_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--wait-for-subscribers",
        action="store_true",
        help="wait (up to --timeout) for a subscriber on each topic before publishing",
    )


def _ros1_play(graph: Any, args: argparse.Namespace) -> None:
    from ros2cmd.bag.play import PlayOptions

    options = PlayOptions(
        rate=args.rate,
        loop=args.loop,
        topics=args.topics,
        start_offset=args.start_offset,
        remaps=_remaps(args.remap),
        wait_for_subscribers=args.wait_for_subscribers,
        ros1=True,
    )
    _run_play(graph, args.bag, options)


def _remaps(rules: list[str]) -> dict[str, str]:
    from ros2cmd.bag.play import parse_remap

    return dict(parse_remap(text) for text in rules)


def _run_play(graph: Any, bag: str, options: Any) -> None:
    from ros2cmd.bag.play import play
    from ros2cmd.graph import until_stopped

    # SIGTERM like Ctrl-C: stop publishing, no traceback from a context shut down under us.
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    if options.loop and options.ros1:  # runs until Ctrl-C: that is its normal end
        with until_stopped():
            play(graph, bag, options)
        return
    play(graph, bag, options)


def _reindex(path: str) -> None:
    from ros2cmd.bag.storage import reindex

    bag = reindex(path)
    print(f"Reindexed {path}: {bag.message_count} messages, metadata.yaml rewritten")


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


def _add_reindex(sub: argparse._SubParsersAction) -> None:
    reindex = sub.add_parser(
        "reindex", help="give an unfinished recording its summary and metadata.yaml"
    )
    reindex.add_argument("bag", help="the bag's folder")
    reindex.set_defaults(run=lambda _graph, a: _reindex(a.bag), offline=True)


def _add_ros1_commands(sub: argparse._SubParsersAction) -> None:
    _ros1_record_arguments(sub.add_parser("record", help="record topics into a new bag"))
    info = sub.add_parser("info", help="what a bag holds")
    info.add_argument("bag", help="the bag's folder (or one .mcap file)")
    info.set_defaults(run=lambda _graph, a: bag_info.print_info(a.bag, True), offline=True)
    _add_reindex(sub)
    play = sub.add_parser("play", parents=[_timeout_option()], help="publish a bag's messages")
    _ros1_play_arguments(play)


def _add_ros2_commands(sub: argparse._SubParsersAction) -> None:
    from ros2cmd.bag import ros2

    ros2.add_info(sub.add_parser("info", help="Print information about a bag to the screen"))
    ros2.add_play(
        sub.add_parser("play", parents=[_timeout_option()], help="Play back ROS data from a bag")
    )
    ros2.add_record(sub.add_parser("record", help="Record ROS data to a bag"))
    _add_reindex(sub)


def register(verbs: argparse._SubParsersAction, _common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("bag", help="bags: record, info, play (rosbag2, MCAP storage)")
    _add_ros2_commands(parser.add_subparsers(dest="command", metavar="COMMAND", required=True))


def rosbag_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="rosbag", description="ROS 1's rosbag, on ROS 2 bags (see: ros2 bag)"
    )
    _add_ros1_commands(parser.add_subparsers(dest="command", metavar="COMMAND", required=True))
    return parser


@exits_130_on_ctrl_c
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
    _add_ros1_commands(parser.add_subparsers(dest="command", required=True))
    args = parser.parse_args([command, *argv])
    try:
        args.run(None, args)
    except ToolError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    except BrokenPipeError:
        stdout_closed()
    return 0
