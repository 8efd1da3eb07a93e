"""`ros2 topic find TYPE [-c]`: the topics that carry the type."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.graph import Graph
from ros2cmd.sub_verbs import add_count_option
from ros2cmd.topic.api import (
    add_graph_options,
    add_hidden_option,
    names_and_types,
)
from ros2cmd.typenames import full_type_name, load_type

HELP = "Output a list of available topics of a given type"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.set_defaults(daemon=True)
    parser.add_argument(
        "topic_type", help="Name of the ROS topic type to filter for (e.g. 'std_msg/msg/String')"
    )
    completion.attach(parser, topic_type=completion.message_types)
    add_count_option(parser, "topics")
    add_hidden_option(parser)
    add_graph_options(parser)


def main(graph: Graph, args: argparse.Namespace) -> None:
    wanted = full_type_name(load_type(args.topic_type, ("msg",)))  # unknown: an error first
    graph.settle()
    found = [
        name
        for name, types in sorted(names_and_types(graph, args.include_hidden_topics).items())
        if wanted in types
    ]
    if args.count_topics:
        print(len(found))
    for name in [] if args.count_topics else found:
        print(name)
