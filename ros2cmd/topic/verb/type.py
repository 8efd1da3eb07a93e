"""`ros2 topic type TOPIC`: the topic's types, one a line."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.graph import Graph, absolute_name
from ros2cmd.topic.api import add_graph_options, wait_for_types

HELP = "Print a topic's type"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.set_defaults(daemon=True)
    parser.add_argument("topic_name", help="Name of the ROS topic to get type (e.g. '/chatter')")
    completion.attach(parser, topic_name=completion.topic_names)
    add_graph_options(parser)


def main(graph: Graph, args: argparse.Namespace) -> None:
    for type_name in wait_for_types(graph, absolute_name(args.topic_name)):
        print(type_name)
