"""`ros2 bag play BAG`: ros2bag's options (verb/play.py, branch jazzy) with its defaults;
what this project does not implement is refused in one line."""

from __future__ import annotations

import argparse
from typing import Any

from ros2cmd.bag.options import (
    remap_argument,
    remaps,
    run_play,
    wait_argument,
)
from ros2cmd.bag.ros2.api import (
    LOG_LEVELS,
    add_reader_arguments,
    check_not_negative_float,
    check_not_negative_int,
    check_positive_float,
    check_storage,
    not_supported,
    positive_float,
    service_event_topics,
    set_log_level,
)

HELP = "Play back ROS data from a bag"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_reader_arguments(parser)
    a = parser.add_argument
    a(
        "--read-ahead-queue-size",
        type=int,
        default=1000,
        help="size of message queue rosbag tries to hold in memory (accepted; messages are "
        "read as they are due here).",
    )
    a(
        "-r",
        "--rate",
        type=check_positive_float,
        default=1.0,
        help="rate at which to play back messages. Valid range > 0.0.",
    )
    a(
        "--topics",
        type=str,
        default=[],
        metavar="topic",
        nargs="+",
        help="Space-delimited list of topics to play.",
    )
    a(
        "--services",
        type=str,
        default=[],
        metavar="service",
        nargs="+",
        help="Space-delimited list of services to play.",
    )
    a(
        "-e",
        "--regex",
        default="",
        help="Play only topics and services matches with regular expression.",
    )
    a(
        "-x",
        "--exclude-regex",
        default="",
        help="regular expressions to exclude topics and services from replay.",
    )
    a(
        "--exclude-topics",
        type=str,
        default=[],
        metavar="topic",
        nargs="+",
        help="Space-delimited list of topics not to play.",
    )
    a(
        "--exclude-services",
        type=str,
        default=[],
        metavar="service",
        nargs="+",
        help="Space-delimited list of services not to play.",
    )
    a("--qos-profile-overrides-path", metavar="PATH", help="(not supported here)")
    a(
        "-l",
        "--loop",
        action="store_true",
        help="enables loop playback when playing a bagfile: it starts back at the beginning "
        "on reaching the end and plays indefinitely.",
    )
    remap_argument(parser)
    a("--storage-config-file", metavar="PATH", help="(not supported here)")
    clock = parser.add_mutually_exclusive_group()
    clock.add_argument(
        "--clock", type=positive_float, nargs="?", const=40, default=0, help="(not supported here)"
    )
    clock.add_argument(
        "--clock-topics", type=str, default=[], nargs="+", help="(not supported here)"
    )
    clock.add_argument(
        "--clock-topics-all", default=False, action="store_true", help="(not supported here)"
    )
    a(
        "-d",
        "--delay",
        type=positive_float,
        default=0.0,
        help="Sleep duration before play (each loop), in seconds. Negative durations invalid.",
    )
    a(
        "--playback-duration",
        type=float,
        default=-1.0,
        help="Playback duration, in seconds. Negative durations mark an infinite playback.",
    )
    until = parser.add_mutually_exclusive_group()
    until.add_argument(
        "--playback-until-sec",
        type=float,
        default=-1.0,
        help="Playback until timestamp, expressed in seconds since epoch.",
    )
    until.add_argument(
        "--playback-until-nsec",
        type=int,
        default=-1,
        help="Playback until timestamp, expressed in nanoseconds since epoch.",
    )
    a(
        "--disable-keyboard-controls",
        action="store_true",
        help="disables keyboard controls for playback",
    )
    a(
        "-p",
        "--start-paused",
        action="store_true",
        default=False,
        help="Start the playback player in a paused state.",
    )
    a(
        "--start-offset",
        type=check_not_negative_float,
        default=0.0,
        help="Start the playback player this many seconds into the bag file.",
    )
    a(
        "--wait-for-all-acked",
        type=check_not_negative_int,
        default=-1,
        metavar="TIMEOUT",
        help="Wait until all published messages are acknowledged by all subscribers or until "
        "the timeout elapses in millisecond before play is terminated.",
    )
    a(
        "--disable-loan-message",
        action="store_true",
        default=False,
        help="Disable to publish as loaned message (accepted; rclpy does not loan).",
    )
    a(
        "--publish-service-requests",
        action="store_true",
        default=False,
        help="Publish recorded service requests instead of recorded service events",
    )
    a(
        "--service-requests-source",
        default="service_introspection",
        choices=["service_introspection", "client_introspection"],
        help="Determine the source of the service requests to be replayed.",
    )
    a("--log-level", type=str, default="info", choices=LOG_LEVELS, help="Logging level.")
    wait_argument(parser)
    parser.set_defaults(run=main, offline=False)


def main(graph: Any, args: argparse.Namespace) -> None:
    from ros2cmd.bag.play import PlayOptions

    check_storage(args.storage)
    for given, what, why in (
        (args.qos_profile_overrides_path, "--qos-profile-overrides-path", "QoS is as recorded"),
        (args.storage_config_file, "--storage-config-file", "mcap's defaults are used"),
        (args.clock, "--clock", "no /clock is published"),
        (args.clock_topics or args.clock_topics_all, "--clock-topics", "no /clock is published"),
    ):
        if given:
            raise not_supported(what, why)
    until = -1
    if args.playback_until_sec >= 0:
        until = int(args.playback_until_sec * 1e9)
    elif args.playback_until_nsec >= 0:
        until = args.playback_until_nsec
    set_log_level(args.log_level, "rosbag2_player", "rosbag2_transport")
    options = PlayOptions(
        rate=args.rate,
        loop=args.loop,
        topics=[t if t.startswith("/") else "/" + t for t in args.topics],
        services=service_event_topics(args.services),
        regex=args.regex,
        exclude_regex=args.exclude_regex,
        exclude_topics=args.exclude_topics,
        exclude_services=service_event_topics(args.exclude_services),
        start_offset=args.start_offset,
        remaps=remaps(args.remap or []),
        wait_for_subscribers=args.wait_for_subscribers,
        delay=args.delay,
        start_paused=args.start_paused,
        keyboard=not args.disable_keyboard_controls,
        playback_duration=args.playback_duration,
        playback_until=until,
        wait_acked_timeout=args.wait_for_all_acked,
        publish_service_requests=args.publish_service_requests,
        client_introspection=args.service_requests_source == "client_introspection",
    )
    run_play(graph, args.bag_path, options)
