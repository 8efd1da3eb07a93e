"""`ros2 action list [-t] [-c]`: the actions (each with its type), or how many."""

from __future__ import annotations

import argparse

from ros2cmd.graph import Graph, print_names
from ros2cmd.sub_verbs import add_count_option

HELP = "Output a list of action names"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.set_defaults(daemon=True)
    parser.add_argument(
        "-t", "--show-types", action="store_true", help="Additionally show the action type"
    )
    add_count_option(parser, "actions")


def main(graph: Graph, args: argparse.Namespace) -> None:
    list_actions(graph, args.show_types, args.count_actions)


def list_actions(graph: Graph, show_types: bool = False, count: bool = False) -> None:
    """`ros2 action list [-t] [-c]`: the actions (each with its type), or how many."""
    if count:
        graph.settle()
        print(len(graph.action_types()))
        return
    print_names(graph, lambda: graph.action_types(), show_types)
