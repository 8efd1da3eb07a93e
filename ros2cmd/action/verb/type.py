"""`ros2 action type ACTION`: its type (each, if servers and clients disagree)."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.graph import Graph, absolute_name

HELP = "Print a action's type"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "action_name", help="Name of the ROS action to get info (e.g. '/fibonacci')"
    )
    completion.attach(parser, action_name=completion.action_names)


def main(graph: Graph, args: argparse.Namespace) -> None:
    print_type(graph, args.action_name)


def print_type(graph: Graph, action: str) -> None:
    """`ros2 action type ACTION`: its type (each, if servers and clients disagree)."""
    action = absolute_name(action)
    types = graph.wait_for(
        lambda: graph.action_types().get(action),
        f"unknown action '{action}': not seen in the graph",
    )
    graph.finish()
    for type_name in types:
        print(type_name)
