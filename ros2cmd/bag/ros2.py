"""`ros2 bag record|play|info`: ROS 2 Jazzy's ros2bag verbs, their options and their checks.

The options are ros2bag's (ros2bag/verb/record.py, play.py, info.py, branch jazzy), with its
defaults and its `[ERROR] [ros2bag]: ...` and `[WARN] [ros2bag]: ...` lines. An option this
project does not implement (compression, snapshots, sim time, QoS override files, splitting)
is refused with one line saying so, rather than silently ignored.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from typing import Any

from ros2cmd.bag.options import (
    add_reindex,
    limit_arguments,
    remap_argument,
    remaps,
    run_play,
    timeout_option,
    wait_argument,
)
from ros2cmd.errors import ToolError

STORAGES = ["mcap", "sqlite3"]  # what a Jazzy install registers
MCAP_PRESETS = ["none", "fastwrite", "zstd_fast", "zstd_small"]  # rosbag2_storage_mcap's
LOG_LEVELS = ["debug", "info", "warn", "error", "fatal"]
SERVICE_EVENT_SUFFIX = "/_service_event"


def print_error(text: str) -> str:
    return f"[ERROR] [ros2bag]: {text}"


def print_warn(text: str) -> str:
    return f"[WARN] [ros2bag]: {text}"


def fail(text: str) -> None:
    """ros2bag's way out: its error line on stderr, exit status 1 (ros2cli's sys.exit(str))."""
    print(print_error(text), file=sys.stderr, flush=True)
    raise SystemExit(1)


def not_supported(what: str, why: str) -> ToolError:
    return ToolError(f"not supported here: {what} ({why})")


def service_event_topics(services: list[str] | None) -> list[str]:
    """ros2bag's convert_service_to_service_event_topic."""
    return [service + SERVICE_EVENT_SUFFIX for service in services or []]


# ros2bag.api's argparse checks


def check_positive_float(value: str) -> float:
    try:
        number = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{value} is not the valid type (float)") from None
    if not (number > 0.0 and math.isfinite(number)):  # nan and inf: never a usable rate
        raise argparse.ArgumentTypeError(f"{value} is not in the valid range (> 0.0)")
    return number


def check_not_negative_float(value: str) -> float:
    try:
        number = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{value} is not the valid type (float)") from None
    if not (number >= 0.0 and math.isfinite(number)):
        raise argparse.ArgumentTypeError(f"Value {value} is less than zero.")
    return number


def check_not_negative_int(value: str) -> int:
    try:
        number = int(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{value} is not the valid type (int)") from None
    if number < 0:
        raise argparse.ArgumentTypeError(f"Value {value} is less than zero.")
    return number


def positive_float(value: str) -> float:
    """play's own check (--delay, --clock): argparse reports "invalid positive_float value"."""
    number = float(value)
    if not (number > 0 and math.isfinite(number)):
        raise ValueError(f"Value {number} is less than or equal to zero.")
    return number


def check_path_exists(value: str) -> str:
    if os.path.exists(value):
        return value
    raise argparse.ArgumentTypeError(f"Bag path '{value}' does not exist!")


def _reader_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("bag_path", type=check_path_exists, help="Bag to open")
    parser.add_argument(
        "-s",
        "--storage",
        default="",
        choices=STORAGES,
        help="Storage implementation of bag. "
        "By default attempts to detect automatically - use this argument to override.",
    )


def _storage(storage: str) -> None:
    if storage == "sqlite3":
        raise not_supported("--storage sqlite3", "bags here are mcap, Jazzy's default storage")


def _set_log_level(level: str, *loggers: str) -> None:
    import rclpy.logging

    severity = getattr(rclpy.logging.LoggingSeverity, level.upper())
    for name in loggers:
        rclpy.logging.set_logger_level(name, severity)


# ros2 bag info


def add_info(parser: argparse.ArgumentParser) -> None:
    _reader_arguments(parser)
    parser.add_argument("-t", "--topic-name", action="store_true", help="Only display topic names.")
    parser.add_argument(
        "-v",
        "--verbose",
        action="store_true",
        help="Display request/response information for services",
    )
    parser.set_defaults(run=_info, offline=True)


def _info(_graph: Any, args: argparse.Namespace) -> None:
    from ros2cmd.bag.info import print_ros2_info

    _storage(args.storage)
    print_ros2_info(args.bag_path, args.topic_name, args.verbose)


# ros2 bag record


def add_record(parser: argparse.ArgumentParser) -> None:
    a = parser.add_argument
    a(
        "-o",
        "--output",
        help="Destination of the bagfile to create, "
        "defaults to a timestamped folder in the current directory.",
    )
    a(
        "-s",
        "--storage",
        default="mcap",
        choices=STORAGES,
        help="Storage identifier to be used, defaults to '%(default)s'.",
    )
    topics = parser.add_mutually_exclusive_group()
    topics.add_argument(
        "topics_positional",
        type=str,
        default=[],
        metavar="[Topic ...]",
        nargs="*",
        help="Space-delimited list of topics to record. (deprecated)",
    )
    topics.add_argument(
        "--topics",
        type=str,
        default=[],
        metavar="Topic",
        nargs="+",
        help="Space-delimited list of topics to record.",
    )
    a(
        "--services",
        type=str,
        metavar="ServiceName",
        nargs="+",
        help="Space-delimited list of services to record.",
    )
    a(
        "--topic-types",
        nargs="+",
        default=[],
        metavar="TopicType",
        help="Space-delimited list of topic types to record.",
    )
    a(
        "-a",
        "--all",
        action="store_true",
        help="Record all topics and services (Exclude hidden topic).",
    )
    a("--all-topics", action="store_true", help="Record all topics (Exclude hidden topic).")
    a("--all-services", action="store_true", help="Record all services via service event topics.")
    a(
        "-e",
        "--regex",
        default="",
        help="Record only topics and services containing provided regular expression. "
        "Note:  --all, --all-topics or --all-services will override --regex.",
    )
    a(
        "--exclude-regex",
        default="",
        help="Exclude topics and services containing provided regular expression. Works on top "
        "of --all, --all-topics, --all-services, --topics, --services or --regex.",
    )
    a(
        "--exclude-topic-types",
        type=str,
        default=[],
        metavar="ExcludeTopicTypes",
        nargs="+",
        help="Space-delimited list of topic types not being recorded. "
        "Works on top of --all, --all-topics, --topics or --regex.",
    )
    a(
        "--exclude-topics",
        type=str,
        metavar="Topic",
        nargs="+",
        help="Space-delimited list of topics not being recorded. "
        "Works on top of --all, --all-topics, --topics or --regex.",
    )
    a(
        "--exclude-services",
        type=str,
        metavar="ServiceName",
        nargs="+",
        help="Space-delimited list of services not being recorded. "
        "Works on top of --all, --all-services, --services or --regex.",
    )
    a(
        "--include-unpublished-topics",
        action="store_true",
        help="Discover and record topics which have no publisher.",
    )
    a(
        "--include-hidden-topics",
        action="store_true",
        help="Discover and record hidden topics as well. "
        "These are topics used internally by ROS 2 implementation.",
    )
    a(
        "--no-discovery",
        action="store_true",
        help="Disables topic auto discovery during recording: only topics present at "
        "startup will be recorded.",
    )
    a(
        "-p",
        "--polling-interval",
        type=int,
        default=100,
        help="Time in ms to wait between querying available topics for recording. "
        "It has no effect if --no-discovery is enabled.",
    )
    a("--ignore-leaf-topics", action="store_true", help="Ignore topics without a subscription.")
    a("--qos-profile-overrides-path", metavar="PATH", help="(not supported here)")
    a(
        "-f",
        "--serialization-format",
        default="",
        choices=["cdr"],
        help="The rmw serialization format in which the messages are saved, defaults to the "
        "rmw currently in use.",
    )
    a(
        "-b",
        "--max-bag-size",
        type=int,
        default=0,
        help="Maximum size in bytes before the bagfile will be split (not supported here; "
        "default %(default)d: no splitting).",
    )
    a(
        "-d",
        "--max-bag-duration",
        type=int,
        default=0,
        help="Maximum duration in seconds before the bagfile will be split (not supported "
        "here; default %(default)d: no splitting).",
    )
    a(
        "--max-cache-size",
        type=int,
        default=100 * 1024 * 1024,
        help="Maximum size (in bytes) of messages to hold in each buffer of cache "
        "(accepted; this recorder writes out at least once a second).",
    )
    a(
        "--disable-keyboard-controls",
        action="store_true",
        default=False,
        help="disables keyboard controls for recorder",
    )
    a(
        "--start-paused",
        action="store_true",
        default=False,
        help="Start the recorder in a paused state.",
    )
    a("--use-sim-time", action="store_true", default=False, help="(not supported here)")
    a(
        "--node-name",
        type=str,
        default="rosbag2_recorder",
        help="Specify the recorder node name. Default is %(default)s.",
    )
    a(
        "--custom-data",
        type=str,
        metavar="KEY=VALUE",
        nargs="*",
        help="Space-delimited list of key=value pairs. Store the custom data in metadata "
        'under the "rosbag2_bagfile_information/custom_data".',
    )
    a("--snapshot-mode", action="store_true", help="(not supported here)")
    a("--log-level", type=str, default="info", choices=LOG_LEVELS, help="Logging level.")
    a("--storage-config-file", metavar="PATH", help="(not supported here)")
    a(
        "--storage-preset-profile",
        type=str,
        default="none",
        choices=MCAP_PRESETS,
        help='Select a preset configuration for storage plugin "mcap" (none and fastwrite here).',
    )
    a("--compression-queue-size", type=int, default=1, help="(compression: not supported here)")
    a("--compression-threads", type=int, default=0, help="(compression: not supported here)")
    a(
        "--compression-threads-priority",
        type=int,
        default=0,
        help="(compression: not supported here)",
    )
    a(
        "--compression-mode",
        type=str,
        default="none",
        choices=["none", "file", "message"],
        help="Choose mode of compression for the storage (only none here).",
    )
    a(
        "--compression-format",
        type=str,
        default="",
        choices=["zstd"],
        help="(compression: not supported here)",
    )
    limit_arguments(parser)
    parser.set_defaults(run=_record)


def _validate_record(args: argparse.Namespace, uri: str) -> None:
    """ros2bag's validate_parsed_arguments, its lines and their order."""
    if args.topics_positional:
        args.topics = args.topics_positional
    if not (
        args.all
        or args.all_topics
        or args.all_services
        or args.services
        or args.topics
        or args.topic_types
        or args.regex
    ):
        fail(
            "Need to specify at least one option out of --all, --all-topics, "
            "--all-services, --services, --topics, --topic-types or --regex"
        )
    every = args.all or args.all_topics or args.topic_types or args.regex
    if args.exclude_regex and not (every or args.all_services):
        fail(
            "--exclude-regex argument requires either --all, "
            "--all-topics, --topic-types, --all-services or --regex"
        )
    if args.exclude_topics and not every:
        fail(
            "--exclude-topics argument requires either --all, --all-topics, "
            "--topic-types or --regex"
        )
    if args.exclude_topic_types and not every:
        fail("--exclude-topic-types argument requires either --all, --all-topics or --regex")
    if args.exclude_services and not (args.all or args.all_services or args.regex):
        fail("--exclude-services argument requires either --all, --all-services or --regex")
    if (args.all or args.all_services) and args.services:
        print(print_warn("--all or --all-services will override --services"))
    if (args.all or args.all_topics) and args.topics:
        print(print_warn("--all or --all-topics will override --topics"))
    if (args.all or args.all_topics or args.all_services) and args.regex:
        print(print_warn("--all, --all-topics or --all-services will override --regex"))
    if os.path.isdir(uri):
        fail(f"Output folder '{uri}' already exists.")
    if args.use_sim_time and args.no_discovery:
        fail(
            "--use-sim-time and --no-discovery both set, but are incompatible settings. "
            "The /clock topic needs to be discovered to record with sim time."
        )
    if args.compression_format and args.compression_mode == "none":
        fail("Invalid choice: Cannot specify compression format without a compression mode.")
    if args.compression_queue_size < 0:
        fail("Compression queue size must be at least 0.")


def _refuse_unsupported_record(args: argparse.Namespace) -> None:
    _storage(args.storage)
    for given, what, why in (
        (args.max_bag_size, "--max-bag-size", "bags are written as one file"),
        (args.max_bag_duration, "--max-bag-duration", "bags are written as one file"),
        (args.use_sim_time, "--use-sim-time", "messages are stamped with the wall clock"),
        (args.snapshot_mode, "--snapshot-mode", "no snapshot service"),
        (args.qos_profile_overrides_path, "--qos-profile-overrides-path", "QoS is matched"),
        (args.storage_config_file, "--storage-config-file", "mcap's defaults are used"),
        (args.compression_mode != "none", "--compression-mode", "chunks are uncompressed"),
        (
            args.storage_preset_profile.startswith("zstd"),
            f"--storage-preset-profile {args.storage_preset_profile}",
            "chunks are uncompressed",
        ),
    ):
        if given:
            raise not_supported(what, why)
    if args.polling_interval <= 0:
        raise ToolError(f"--polling-interval {args.polling_interval}: must be above 0 ms")


def _record(graph: Any, args: argparse.Namespace) -> None:
    import datetime

    from ros2cmd.bag.record import RecordOptions, record

    uri = args.output or datetime.datetime.now().strftime("rosbag2_%Y_%m_%d-%H_%M_%S")
    _validate_record(args, uri)
    _refuse_unsupported_record(args)
    custom_data = {}
    for pair in args.custom_data or []:
        key, separator, value = pair.partition("=")
        if not separator:
            raise ToolError(f"--custom-data '{pair}': expected KEY=VALUE")
        custom_data[key] = value
    _set_log_level(args.log_level, args.node_name, "rosbag2_cpp", "rosbag2_transport")
    options = RecordOptions(
        topics=args.topics,
        services=service_event_topics(args.services),
        all_topics=args.all_topics or args.all,
        all_services=args.all_services or args.all,
        topic_types=args.topic_types,
        regex=args.regex,
        exclude_regex=args.exclude_regex,
        exclude_topic_types=args.exclude_topic_types,
        exclude_topics=args.exclude_topics or [],
        exclude_services=service_event_topics(args.exclude_services),
        include_unpublished_topics=args.include_unpublished_topics,
        include_hidden_topics=args.include_hidden_topics,
        ignore_leaf_topics=args.ignore_leaf_topics,
        no_discovery=args.no_discovery,
        polling_interval=args.polling_interval / 1000,
        start_paused=args.start_paused,
        keyboard=not args.disable_keyboard_controls,
        node_name=args.node_name,
        duration=args.duration,
        max_messages=args.max_messages,
        custom_data=custom_data or None,
    )
    record(graph, options, uri)


# ros2 bag play


def add_play(parser: argparse.ArgumentParser) -> None:
    _reader_arguments(parser)
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
    parser.set_defaults(run=_play, offline=False)


def _play(graph: Any, args: argparse.Namespace) -> None:
    from ros2cmd.bag.play import PlayOptions

    _storage(args.storage)
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
    _set_log_level(args.log_level, "rosbag2_player", "rosbag2_transport")
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


def register(verbs: argparse._SubParsersAction, _common: argparse.ArgumentParser) -> None:
    """`ros2 bag info|play|record|reindex`."""
    parser = verbs.add_parser("bag", help="bags: record, info, play (rosbag2, MCAP storage)")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    add_info(sub.add_parser("info", help="Print information about a bag to the screen"))
    add_play(
        sub.add_parser("play", parents=[timeout_option()], help="Play back ROS data from a bag")
    )
    add_record(sub.add_parser("record", help="Record ROS data to a bag"))
    add_reindex(sub)
