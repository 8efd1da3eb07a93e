"""`ros2 topic list [-t] [-c] [-v] [--include-hidden-topics]`."""

from __future__ import annotations

import argparse

from ros2cmd.graph import Graph
from ros2cmd.sub_verbs import add_count_option
from ros2cmd.topic.api import (
    add_graph_options,
    add_hidden_option,
    names_and_types,
)

HELP = "Output a list of available topics"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.set_defaults(daemon=lambda a: not a.verbose)  # -v counts endpoints: a node of its own
    parser.add_argument(
        "-t", "--show-types", action="store_true", help="Additionally show the topic type"
    )
    add_count_option(parser, "topics")
    add_hidden_option(parser)
    parser.add_argument(
        "-v", "--verbose", action="store_true", help="List full details about each topic"
    )
    add_graph_options(parser)


def main(graph: Graph, args: argparse.Namespace) -> None:
    graph.settle()
    topics = sorted(names_and_types(graph, args.include_hidden_topics).items())
    if args.count_topics:
        print(len(topics))
        return
    if args.verbose:
        for title, count, noun in (
            ("Published", graph.node.count_publishers, "publisher"),
            ("Subscribed", graph.node.count_subscribers, "subscriber"),
        ):
            print(f"{title} topics:")
            for name, types in topics:
                n = count(name)
                if n:
                    print(f" * {name} [{', '.join(types)}] {n} {noun}{'s' if n > 1 else ''}")
            print()
        return
    for name, types in topics:
        print(f"{name} [{', '.join(types)}]" if args.show_types else name)
