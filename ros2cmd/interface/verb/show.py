"""`ros2 interface show TYPE [--all-comments | --no-comments]`: the definition, expanded."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.interface.api import show

HELP = "Output the interface definition"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    comments = parser.add_mutually_exclusive_group()
    comments.add_argument(
        "--all-comments",
        action="store_true",
        help="Show all comments, including for nested interface definitions",
    )
    comments.add_argument(
        "--no-comments", action="store_true", help="Show no comments or whitespace"
    )
    parser.add_argument(
        "type",
        help="Show an interface definition (e.g. 'example_interfaces/msg/String'). Passing '-' "
        "reads the argument from stdin (e.g. 'ros2 topic type /chatter | ros2 interface show -').",
    )
    completion.attach(parser, type=completion.all_types)


def main(_graph: object, args: argparse.Namespace) -> None:
    show(args.type, comments=not args.no_comments, all_comments=args.all_comments)
