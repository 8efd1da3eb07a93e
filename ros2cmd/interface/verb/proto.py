"""`ros2 interface proto TYPE`: the YAML a `topic pub` takes, quoted."""

from __future__ import annotations

import argparse
import sys

from ros2cmd import completion
from ros2cmd.typenames import load_type, parse_type_name

HELP = "Output an interface prototype"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "type", help="Show an interface definition (e.g. 'example_interfaces/msg/String')"
    )
    completion.attach(parser, type=completion.all_types)
    parser.add_argument(
        "--no-quotes", action="store_true", help="if true output has no outer quotes."
    )


def main(_graph: object, args: argparse.Namespace) -> None:
    proto(args.type, quotes=not args.no_quotes)


def proto(type_name: str, quotes: bool = True) -> None:
    """`ros2 interface proto`: a default message (a goal, a request) as YAML."""
    import yaml

    from ros2cmd.messages import message_to_data  # loads rclpy's generated classes: only here

    cls = load_type(type_name)
    kind = parse_type_name(type_name)[1]
    instance = cls.Goal() if kind == "action" else cls.Request() if kind == "srv" else cls()
    # rosidl_runtime_py's message_to_yaml: block style, lines never wrapped, "{}\n" if empty.
    text = yaml.safe_dump(
        message_to_data(instance),
        default_flow_style=False,
        sort_keys=False,
        allow_unicode=True,
        width=sys.maxsize,
    )
    print(f'"{text}"' if quotes else text)
