"""`ros2 service info SERVICE`: its type, how many clients and servers it has (with -v, which
nodes: an addition of this project; Jazzy's ros2service has no -v)."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.graph import Graph, absolute_name, split_node_name
from ros2cmd.service.api import add_hidden_option, service_types, wait_for_types, with_hidden

HELP = "Print information about a service"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("service_name", help="Name of the ROS service (e.g. '/add_two_ints')")
    completion.attach(parser, service_name=completion.service_names)
    parser.add_argument("-v", "--verbose", action="store_true", help="also name the nodes")
    add_hidden_option(parser)


def main(graph: Graph, args: argparse.Namespace) -> None:
    include_hidden = with_hidden(args)
    service = absolute_name(args.service_name)
    wait_for_types(graph, service, include_hidden)
    graph.settle()  # the first endpoint made it known; let every other one arrive too
    types = service_types(graph, include_hidden).get(service, [])
    print(f"Type: {types[0] if len(types) == 1 else types}")
    clients, servers = _nodes_with(graph, service) if args.verbose else ([], [])
    for title, count, nodes in (
        ("Clients", graph.node.count_clients(service), clients),
        ("Services", graph.node.count_services(service), servers),
    ):
        print(f"{title} count: {count}")
        for node in nodes:
            print(f"  Node: {node}")


def _nodes_with(graph: Graph, service: str) -> tuple[list[str], list[str]]:
    """The full names of the nodes that are clients and servers of a service."""
    clients, servers = [], []
    for full in graph.node_names():
        namespace, name = split_node_name(full)
        try:
            served = graph.node.get_service_names_and_types_by_node(name, namespace)
            asked = graph.node.get_client_names_and_types_by_node(name, namespace)
        except RuntimeError:  # rclpy's NodeNameNonExistentError: it has just gone
            continue
        if any(found == service for found, _ in asked):
            clients.append(full)
        if any(found == service for found, _ in served):
            servers.append(full)
    return clients, servers
