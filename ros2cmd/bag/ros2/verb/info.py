"""`ros2 bag info BAG [-t] [-v]`: what a bag holds, as ros2bag prints it."""

from __future__ import annotations

import argparse
from typing import Any

from ros2cmd.bag.ros2.api import (
    add_reader_arguments,
    check_storage,
)

HELP = "Print information about a bag to the screen"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_reader_arguments(parser)
    parser.add_argument("-t", "--topic-name", action="store_true", help="Only display topic names.")
    parser.add_argument(
        "-v",
        "--verbose",
        action="store_true",
        help="Display request/response information for services",
    )
    parser.set_defaults(run=main, offline=True)


def main(_graph: Any, args: argparse.Namespace) -> None:
    from ros2cmd.bag.info import print_ros2_info

    check_storage(args.storage)
    print_ros2_info(args.bag_path, args.topic_name, args.verbose)
