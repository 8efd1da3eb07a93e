"""`ros2 bag record`: ros2bag's options (verb/record.py, branch jazzy) with its defaults and
checks, in its order; what this project does not implement is refused in one line."""

from __future__ import annotations

import argparse
import os
from typing import Any

from ros2cmd import completion
from ros2cmd.bag.options import (
    limit_arguments,
)
from ros2cmd.bag.ros2.api import (
    LOG_LEVELS,
    MCAP_PRESETS,
    STORAGES,
    check_storage,
    fail,
    not_supported,
    print_warn,
    service_event_topics,
    set_log_level,
)
from ros2cmd.errors import ToolError

HELP = "Record ROS data to a bag"


def add_arguments(parser: argparse.ArgumentParser) -> None:
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
    completion.attach(
        parser, topics_positional=completion.topic_names, topics=completion.topic_names
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
    parser.set_defaults(run=main)


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
    check_storage(args.storage)
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


def main(graph: Any, args: argparse.Namespace) -> None:
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
    set_log_level(args.log_level, args.node_name, "rosbag2_cpp", "rosbag2_transport")
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
