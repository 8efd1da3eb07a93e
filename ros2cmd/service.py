"""`ros2 service ...`: list services, show their types, and call them (like `ros2 service`)."""

from __future__ import annotations

import argparse
from typing import Any

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, ServiceInfo, absolute_name, add_list_and_type, print_names
from ros2cmd.messages import fill_message, message_to_yaml, parse_yaml
from ros2cmd.typenames import full_type_name, load_type


def list_services(graph: Graph, show_types: bool = False) -> None:
    print_names(graph, graph.service_types, show_types)


def print_type(graph: Graph, service: str) -> None:
    print(graph.wait_for_service_type(absolute_name(service)))


def find(graph: Graph, type_name: str) -> None:
    wanted = full_type_name(load_type(type_name, ("srv",)))  # an unknown type: an error first
    print_names(graph, graph.service_types, of_type=wanted)


def servers(graph: Graph, service: str) -> list[str]:
    """The nodes that offer a service, once the graph is complete (and one is known)."""
    graph.settle()
    return graph.wait_for(
        lambda: graph.snapshot().services.get(service, ServiceInfo([])).servers,
        f"service '{service}': the node that serves it is not known",
    )


def call(
    graph: Graph, service: str, type_name: str | None, values: Any, ros1_output: bool = False
) -> Any:
    """Call a service with a request filled from `values` (a dict, or a list in field order).

    Prints what `ros2 service call` prints, or with ros1_output the response as YAML as
    `rosservice call` did (``result: 15``). Returns the response.
    """
    service = absolute_name(service)
    srv_type = load_type(type_name, ("srv",)) if type_name else None
    request = fill_message(srv_type.Request(), values) if srv_type else None  # check input first
    offered = graph.wait_for_service_type(service)
    if srv_type is None:
        srv_type = load_type(offered, ("srv",))
        request = fill_message(srv_type.Request(), values)
    elif full_type_name(srv_type) != offered:
        raise ToolError(f"service '{service}' has type {offered}, not {full_type_name(srv_type)}")
    client = graph.node.create_client(srv_type, service)
    if not ros1_output:
        print(f"requester: making request: {request}\n", flush=True)
    response = graph.call(client, request, f"cannot call '{service}'")
    graph.finish()
    print(message_to_yaml(response) if ros1_output else f"response:\n{response}")
    return response


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("service", help="services: list, type, call, find")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    add_list_and_type(sub, common, "service", list_services, print_type)

    p = sub.add_parser("call", parents=[common], help="call a service with a request as YAML")
    p.add_argument("service")
    p.add_argument("type", help="service type, e.g. ros_tutorials_interfaces/srv/SrvTutorial")
    p.add_argument("values", nargs="?", default="{}", help="the request as YAML, e.g. '{a: 1}'")
    p.set_defaults(run=lambda graph, a: call(graph, a.service, a.type, parse_yaml(a.values)))

    p = sub.add_parser("find", parents=[common], help="list the services of a type")
    p.add_argument("type")
    p.set_defaults(daemon=True, run=lambda graph, a: find(graph, a.type))
