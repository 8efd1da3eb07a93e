"""`ros2 service find TYPE [-c]`: the services of a type, once the graph is complete."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.graph import Graph
from ros2cmd.service.api import add_hidden_option, service_types, with_hidden
from ros2cmd.sub_verbs import add_count_option
from ros2cmd.typenames import full_type_name, load_type

HELP = "Output a list of available services of a given type"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "service_type", help="Name of the ROS service type (e.g. 'std_srvs/srv/Empty')"
    )
    completion.attach(parser, service_type=completion.service_types)
    add_count_option(parser, "services")
    add_hidden_option(parser)
    parser.set_defaults(daemon=True)


def main(graph: Graph, args: argparse.Namespace) -> None:
    find(graph, args.service_type, args.count_services, with_hidden(args))


def find(graph: Graph, type_name: str, count: bool = False, include_hidden: bool = False) -> None:
    wanted = full_type_name(load_type(type_name, ("srv",)))  # an unknown type: an error first
    graph.settle()
    found = service_types(graph, include_hidden)
    names = sorted(name for name, types in found.items() if wanted in types)
    if count:
        print(len(names))
    for name in [] if count else names:
        print(name)
