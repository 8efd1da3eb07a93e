"""`ros2 node ...`: the nodes in the graph and what each one offers (like `ros2 node`)."""

from __future__ import annotations

import argparse
import sys

from rclpy.action.graph import (
    get_action_client_names_and_types_by_node,
    get_action_server_names_and_types_by_node,
)

from ros2cmd.graph import Graph, split_node_name

# What `ros2 node list` and `ros2 node info` print (to stderr) for nodes of one name.
DUPLICATES_WARNING = (
    "WARNING: Be aware that there are nodes in the graph that share an exact name, "
    "which can have unintended side effects."
)
INFO_DUPLICATES_WARNING = (
    'There are {count} nodes in the graph with the exact name "{name}". '
    "You are seeing information about only one of them."
)


def list_nodes(graph: Graph) -> None:
    graph.settle()
    names = graph.node_names()
    if len(set(names)) < len(names):
        print(DUPLICATES_WARNING, file=sys.stderr)
    for name in names:
        print(name)


def info(graph: Graph, full_name: str) -> None:
    full_name = graph.wait_for_node(full_name)
    namespace, name = split_node_name(full_name)
    graph.settle()  # the node is known; let its endpoints arrive too
    count = graph.node_names().count(full_name)
    if count > 1:
        print(INFO_DUPLICATES_WARNING.format(count=count, name=full_name), file=sys.stderr)
    node = graph.node
    sections = {
        "Subscribers": node.get_subscriber_names_and_types_by_node(name, namespace),
        "Publishers": node.get_publisher_names_and_types_by_node(name, namespace),
        "Service Servers": node.get_service_names_and_types_by_node(name, namespace),
        "Service Clients": node.get_client_names_and_types_by_node(name, namespace),
        "Action Servers": get_action_server_names_and_types_by_node(node, name, namespace),
        "Action Clients": get_action_client_names_and_types_by_node(node, name, namespace),
    }
    print(full_name)
    for title, endpoints in sections.items():
        print(f"  {title}:")
        for endpoint, types in sorted(endpoints):
            print(f"    {endpoint}: {', '.join(types)}")


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("node", help="nodes: list, info")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    p = sub.add_parser("list", parents=[common], help="list the nodes in the graph")
    p.set_defaults(daemon=True, run=lambda graph, a: list_nodes(graph))

    p = sub.add_parser("info", parents=[common], help="what a node publishes, subscribes, offers")
    p.add_argument("node")
    p.set_defaults(run=lambda graph, a: info(graph, a.node))
