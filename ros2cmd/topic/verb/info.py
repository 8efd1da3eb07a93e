"""`ros2 topic info [-v] TOPIC`: the type and the counts; -v each endpoint as rclpy prints it
(node, type, type hash, GID, QoS), every line followed by a blank one."""

from __future__ import annotations

import argparse
import contextlib

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name
from ros2cmd.topic.api import add_graph_options, names_and_types, node_names_known, wait_for_types

HELP = "Print information about a topic"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    # -v prints each endpoint's GID and QoS: a node of its own.
    parser.set_defaults(daemon=lambda a: not a.verbose and {"topic": absolute_name(a.topic_name)})
    parser.add_argument("topic_name", help="Name of the ROS topic to get info (e.g. '/chatter')")
    completion.attach(parser, topic_name=completion.topic_names)
    parser.add_argument(
        "--verbose",
        "-v",
        action="store_true",
        help="Prints detailed information like the node name, node namespace, topic type, "
        "topic type hash, GUID, and QoS Profile of the publishers and subscribers to this topic",
    )
    add_graph_options(parser)


def main(graph: Graph, args: argparse.Namespace) -> None:
    topic = absolute_name(args.topic_name)
    wait_for_types(graph, topic)
    graph.settle()  # every endpoint that was there when the command started is counted
    if args.verbose:
        with contextlib.suppress(ToolError):  # after --timeout, print what is known
            graph.wait_for(lambda: node_names_known(graph, topic), "")
    types = names_and_types(graph, hidden=True)[topic]
    sections = (
        ("Publisher", graph.node.get_publishers_info_by_topic(topic)),
        ("Subscription", graph.node.get_subscriptions_info_by_topic(topic)),
    )
    end = "\n\n" if args.verbose else "\n"
    print(f"Type: {types[0] if len(types) == 1 else types}", end=end)
    for title, endpoints in sections:
        print(f"{title} count: {len(endpoints)}", end=end)
        if args.verbose:
            for endpoint in endpoints:
                print(endpoint, end=end)
