"""`ros2 service list [-t] [-c]`, once the graph is complete."""

from __future__ import annotations

import argparse

from ros2cmd.graph import Graph
from ros2cmd.service.api import add_hidden_option, service_types, with_hidden
from ros2cmd.sub_verbs import add_count_option

HELP = "Output a list of available services"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "-t", "--show-types", action="store_true", help="Additionally show the service type"
    )
    add_count_option(parser, "services")
    add_hidden_option(parser)
    parser.set_defaults(daemon=True)


def main(graph: Graph, args: argparse.Namespace) -> None:
    list_services(graph, args.show_types, args.count_services, with_hidden(args))


def list_services(
    graph: Graph, show_types: bool = False, count: bool = False, include_hidden: bool = False
) -> None:
    graph.settle()
    services = sorted(service_types(graph, include_hidden).items())
    if count:
        print(len(services))
        return
    for name, types in services:
        print(f"{name} [{', '.join(types)}]" if show_types else name)
