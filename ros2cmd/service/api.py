"""What `ros2 service`'s sub-verbs (verb/) and ROS 1's rosservice (ros1/rosservice.py) share:
the services and their types, the nodes that serve one, and the options the sub-verbs share."""

from __future__ import annotations

import argparse

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, ServiceInfo, is_hidden


def service_types(graph: Graph, include_hidden: bool = False) -> dict[str, list[str]]:
    """The services in the graph (with a server or a client) and their types."""
    found = graph.node.get_service_names_and_types()
    return {name: types for name, types in found if include_hidden or not is_hidden(name)}


def wait_for_types(graph: Graph, service: str, include_hidden: bool = True) -> list[str]:
    """The types of a service once a server or client of it is seen (ToolError after the
    timeout). A hidden one is known only with include_hidden, as in ros2cli."""
    types = graph.wait_for(
        lambda: service_types(graph, include_hidden=True).get(service),
        f"unknown service '{service}': no server or client seen",
    )
    if is_hidden(service) and not include_hidden:
        raise ToolError(f"'{service}' is a hidden service; add --include-hidden-services")
    return types


def servers(graph: Graph, service: str) -> list[str]:
    """The nodes that offer a service, once the graph is complete (and one is known)."""
    graph.settle()
    return graph.wait_for(
        lambda: graph.snapshot().services.get(service, ServiceInfo([])).servers,
        f"service '{service}': the node that serves it is not known",
    )


def add_hidden_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--include-hidden-services",
        action="store_true",
        help="Consider hidden services as well",
    )


def with_hidden(args: argparse.Namespace) -> bool:
    """--include-hidden-services, given before the sub-verb or after it."""
    return args.hidden_before or getattr(args, "include_hidden_services", False)
