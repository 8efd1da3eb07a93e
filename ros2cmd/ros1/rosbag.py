"""`rosbag record|info|play|reindex`: ROS 1's rosbag (seed 004) on the code of `ros2 bag`.

It takes ROS 1's short options (`-O`, `-r`, `-l`, `-s`, durations like `5m`) and prints ROS 1's
info fields; ros2cmd/bag/ does the work for both spellings.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from typing import Any

from ros2cmd import completion
from ros2cmd.bag import info as bag_info
from ros2cmd.bag.options import (
    add_reindex,
    limit_arguments,
    offset_seconds,
    remap_argument,
    remaps,
    run_play,
    timeout_option,
    wait_argument,
)
from ros2cmd.errors import ToolError
from ros_tutorials_common.cli import positive_rate
from ros_tutorials_common.shutdown import program_main


def _record_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topics", nargs="*", metavar="TOPIC", help="topics to record")
    completion.attach(parser, topics=completion.topic_names)
    parser.add_argument("-a", "--all", action="store_true", help="all topics, also later ones")
    output = parser.add_mutually_exclusive_group()
    output.add_argument("-o", "--output", help="the bag's folder (default rosbag2_<date-time>)")
    output.add_argument("-O", dest="output", help="the same as -o")
    limit_arguments(parser)
    parser.set_defaults(run=_record)


def _record(graph: Any, args: argparse.Namespace) -> None:
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


def _play_arguments(parser: argparse.ArgumentParser) -> None:
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
    remap_argument(parser)
    wait_argument(parser)
    parser.set_defaults(run=_play, offline=False)


def _play(graph: Any, args: argparse.Namespace) -> None:
    from ros2cmd.bag.play import PlayOptions

    options = PlayOptions(
        rate=args.rate,
        loop=args.loop,
        topics=args.topics,
        start_offset=args.start_offset,
        remaps=remaps(args.remap),
        wait_for_subscribers=args.wait_for_subscribers,
        ros1=True,
    )
    run_play(graph, args.bag, options)


def _add_commands(sub: argparse._SubParsersAction) -> None:
    _record_arguments(sub.add_parser("record", help="record topics into a new bag"))
    info = sub.add_parser("info", help="what a bag holds")
    info.add_argument("bag", help="the bag's folder (or one .mcap file)")
    info.set_defaults(run=lambda _graph, a: bag_info.print_info(a.bag, True), offline=True)
    add_reindex(sub)
    play = sub.add_parser("play", parents=[timeout_option()], help="publish a bag's messages")
    _play_arguments(play)


def rosbag_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="rosbag", description="ROS 1's rosbag, on ROS 2 bags (see: ros2 bag)"
    )
    _add_commands(parser.add_subparsers(dest="command", metavar="COMMAND", required=True))
    return parser


@program_main  # the console script's entry
def rosbag(argv: Sequence[str] | None = None) -> int:
    completion.answer(rosbag_parser())  # the shell asking for TAB's completions: ends here
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv[:1] in (["info"], ["reindex"]):  # offline: no rclpy to load
        return _offline_only(argv[0], argv[1:])
    # record and play run a graph node (ros2cmd.cli's execute): imported for them only.
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
    _add_commands(parser.add_subparsers(dest="command", required=True))
    args = parser.parse_args([command, *argv])
    try:
        args.run(None, args)
    except ToolError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    return 0
