"""`ros2 service type SERVICE`: its type, one line per type (several if servers differ)."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.graph import Graph, absolute_name
from ros2cmd.service.api import add_hidden_option, wait_for_types, with_hidden

HELP = "Output a service's type"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.set_defaults(daemon=True)
    parser.add_argument("service_name", help="Name of the ROS service (e.g. '/clear')")
    completion.attach(parser, service_name=completion.service_names)
    add_hidden_option(parser)


def main(graph: Graph, args: argparse.Namespace) -> None:
    print_type(graph, args.service_name, with_hidden(args))


def print_type(graph: Graph, service: str, include_hidden: bool = False) -> None:
    for type_name in wait_for_types(graph, absolute_name(service), include_hidden):
        print(type_name)
