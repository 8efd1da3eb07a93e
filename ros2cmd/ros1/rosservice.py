"""`rosservice list|type|call|args|info|find`: ROS 1's rosservice on `ros2 service`'s code.

    rosservice call /ros_tutorial_srv 10 5       the request's fields in order (seed 002)

Each command runs ros2cmd/service/'s code; `call` prints the response as YAML, as ROS 1 did
(``sum: 15``), and `args` and `info` read the request's fields.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence

from ros2cmd import completion
from ros2cmd.graph import Graph, absolute_name
from ros2cmd.messages import fill_message, message_to_yaml
from ros2cmd.ros1 import tool
from ros2cmd.service.api import servers, wait_for_types
from ros2cmd.service.verb.find import find
from ros2cmd.service.verb.list import list_services
from ros2cmd.service.verb.type import print_type
from ros2cmd.typenames import load_type
from ros_tutorials_common.shutdown import program_main


def rosservice_parser() -> argparse.ArgumentParser:
    parser, sub, common = tool.new_parser(
        "rosservice", "ROS 1's rosservice, on ROS 2 (ros2 service)"
    )

    p = sub.add_parser("list", parents=[common], help="list services")
    p.set_defaults(daemon=True, run=lambda graph, a: list_services(graph))

    p = sub.add_parser("type", parents=[common], help="service type")
    p.add_argument("service")
    completion.attach(p, service=completion.service_names)
    p.set_defaults(daemon=True, run=lambda graph, a: print_type(graph, a.service))

    p = sub.add_parser("call", parents=[common], help="call a service")
    p.add_argument("service")
    completion.attach(p, service=completion.service_names)
    p.add_argument("values", nargs="*", help="a YAML mapping, or field values in order")
    p.set_defaults(run=_call)

    p = sub.add_parser("args", parents=[common], help="request fields")
    p.add_argument("service")
    completion.attach(p, service=completion.service_names)
    p.set_defaults(run=lambda graph, a: _service_args(graph, a.service))

    p = sub.add_parser("info", parents=[common], help="node, type, args")
    p.add_argument("service")
    completion.attach(p, service=completion.service_names)
    p.set_defaults(run=lambda graph, a: _service_info(graph, a.service))

    p = sub.add_parser("find", parents=[common], help="services of a type")
    p.add_argument("type")
    completion.attach(p, type=completion.ros1_service_types)
    p.set_defaults(daemon=True, run=lambda graph, a: find(graph, a.type))
    tool.no_ros2_meaning("rosservice", sub)
    return parser


def _call(graph: Graph, args: argparse.Namespace) -> None:
    values = tool.values_from_args(args.values)
    if values is None:  # ROS 1 refused a call without its values: no silent default request
        values = []
    service = absolute_name(args.service)
    srv_type = load_type(wait_for_types(graph, service)[0], ("srv",))
    request = fill_message(srv_type.Request(), values)
    client = graph.node.create_client(srv_type, service)
    response = graph.call(client, request, f"cannot call '{service}'")
    graph.finish()
    print(message_to_yaml(response))


def _request_fields(graph: Graph, name: str) -> tuple[str, list[str]]:
    type_name = graph.wait_for_service_type(absolute_name(name))
    fields = load_type(type_name, ("srv",)).Request.get_fields_and_field_types()
    return type_name, list(fields)


def _service_args(graph: Graph, name: str) -> None:
    print(" ".join(_request_fields(graph, name)[1]))


def _service_info(graph: Graph, name: str) -> None:
    type_name, fields = _request_fields(graph, name)
    print(f"Node: {', '.join(servers(graph, absolute_name(name)))}")
    print(f"Type: {type_name}")
    print(f"Args: {' '.join(fields)}")


@program_main  # the console script's entry
def rosservice(argv: Sequence[str] | None = None) -> int:
    return tool.run(rosservice_parser(), argv)
