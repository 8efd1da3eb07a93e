"""`ros2 service ...`: list, type, find, info, call and echo services (ROS 2 Jazzy's ros2service).

Output as ros2service prints it: `list -t` gives ``/clear [std_srvs/srv/Empty]``, `info` its
``Type:``, ``Clients count:`` and ``Services count:`` lines, `call` the request and the response
as Python writes them (``requester: making request: turtlesim.srv.Spawn_Request(...)``, a blank
line, ``response:``, ``turtlesim.srv.Spawn_Response(name='turtle2')``). `echo` shows what service
introspection publishes on ``SERVICE/_service_event`` (service_msgs/msg/ServiceEventInfo and the
request or response), as YAML with the event type's name, once a client or server has it on
(``configure_introspection``; the demo_nodes_cpp introspection demo turns it on by parameter).
"""

from __future__ import annotations

import argparse
import sys
import time
from collections import deque
from typing import Any

import yaml
from rclpy.qos import qos_profile_services_default
from service_msgs.msg import ServiceEventInfo

from ros2cmd.errors import ToolError
from ros2cmd.graph import (
    Graph,
    ServiceInfo,
    absolute_name,
    is_hidden,
    split_node_name,
    until_stopped,
)
from ros2cmd.messages import (
    MessageDumper,
    fill_message,
    message_to_csv,
    message_to_ordered,
    message_to_yaml,
    parse_yaml,
)
from ros2cmd.typenames import full_type_name, load_type
from ros_tutorials_common.cli import positive_rate

DEFAULT_TRUNCATE_LENGTH = 128  # `ros2 service echo` shortens longer strings and arrays
WAITING = "waiting for service to become available..."
# How long `call` looks for the service before it says it is waiting (discovery usually
# finds a running server within a few hundred milliseconds).
QUIET_WAIT = 1.0
EVENT_SUFFIX = "/_service_event"  # rclpy's (and rcl's) introspection topic: SERVICE + this
EVENT_TYPES = {
    getattr(ServiceEventInfo, name): name
    for name in ("REQUEST_SENT", "REQUEST_RECEIVED", "RESPONSE_SENT", "RESPONSE_RECEIVED")
}


def service_types(graph: Graph, include_hidden: bool = False) -> dict[str, list[str]]:
    """The services in the graph (with a server or a client) and their types."""
    found = graph.node.get_service_names_and_types()
    return {name: types for name, types in found if include_hidden or not is_hidden(name)}


def list_services(
    graph: Graph, show_types: bool = False, count: bool = False, include_hidden: bool = False
) -> None:
    """`ros2 service list [-t] [-c]`, once the graph is complete."""
    graph.settle()
    services = sorted(service_types(graph, include_hidden).items())
    if count:
        print(len(services))
        return
    for name, types in services:
        print(f"{name} [{', '.join(types)}]" if show_types else name)


def _wait_for_types(graph: Graph, service: str, include_hidden: bool = True) -> list[str]:
    """The types of a service once a server or client of it is seen (ToolError after the
    timeout). A hidden one is known only with include_hidden, as in ros2cli."""
    types = graph.wait_for(
        lambda: service_types(graph, include_hidden=True).get(service),
        f"unknown service '{service}': no server or client seen",
    )
    if is_hidden(service) and not include_hidden:
        raise ToolError(f"'{service}' is a hidden service; add --include-hidden-services")
    return types


def print_type(graph: Graph, service: str, include_hidden: bool = False) -> None:
    """`ros2 service type SERVICE`: its type, one line per type (several if servers differ)."""
    for type_name in _wait_for_types(graph, absolute_name(service), include_hidden):
        print(type_name)


def find(graph: Graph, type_name: str, count: bool = False, include_hidden: bool = False) -> None:
    """`ros2 service find TYPE [-c]`: the services of a type, once the graph is complete."""
    wanted = full_type_name(load_type(type_name, ("srv",)))  # an unknown type: an error first
    graph.settle()
    found = service_types(graph, include_hidden)
    names = sorted(name for name, types in found.items() if wanted in types)
    if count:
        print(len(names))
    for name in [] if count else names:
        print(name)


def servers(graph: Graph, service: str) -> list[str]:
    """The nodes that offer a service, once the graph is complete (and one is known)."""
    graph.settle()
    return graph.wait_for(
        lambda: graph.snapshot().services.get(service, ServiceInfo([])).servers,
        f"service '{service}': the node that serves it is not known",
    )


def _nodes_with(graph: Graph, service: str) -> tuple[list[str], list[str]]:
    """The full names of the nodes that are clients and servers of a service."""
    clients, servers_ = [], []
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
            servers_.append(full)
    return clients, servers_


def info(graph: Graph, service: str, verbose: bool = False, include_hidden: bool = False) -> None:
    """`ros2 service info SERVICE`: its type, how many clients and servers it has (with -v,
    which nodes: an addition of this project; Jazzy's ros2service has no -v)."""
    service = absolute_name(service)
    _wait_for_types(graph, service, include_hidden)
    graph.settle()  # the first endpoint made it known; let every other one arrive too
    types = service_types(graph, include_hidden).get(service, [])
    print(f"Type: {types[0] if len(types) == 1 else types}")
    clients, servers_ = _nodes_with(graph, service) if verbose else ([], [])
    for title, count, nodes in (
        ("Clients", graph.node.count_clients(service), clients),
        ("Services", graph.node.count_services(service), servers_),
    ):
        print(f"{title} count: {count}")
        for node in nodes:
            print(f"  Node: {node}")


def call(
    graph: Graph,
    service: str,
    type_name: str | None,
    values: Any,
    ros1_output: bool = False,
    period: float | None = None,
) -> Any:
    """Call a service with a request filled from `values` (a dict, or a list in field order).

    Prints what `ros2 service call` prints, or with ros1_output the response as YAML as
    `rosservice call` did (``result: 15``). With a period, calls again every period seconds
    until Ctrl-C (`ros2 service call -r RATE`). Returns the (last) response.
    """
    service = absolute_name(service)
    srv_type = load_type(type_name, ("srv",)) if type_name else None
    request = fill_message(srv_type.Request(), values) if srv_type else None  # check input first
    offered = _wait_until_offered(graph, service, quiet=ros1_output)
    if srv_type is None:
        srv_type = load_type(offered, ("srv",))
        request = fill_message(srv_type.Request(), values)
    elif full_type_name(srv_type) != offered:
        raise ToolError(f"service '{service}' has type {offered}, not {full_type_name(srv_type)}")
    client = graph.node.create_client(srv_type, service)
    if period is not None:
        with until_stopped():
            while True:
                started = time.monotonic()
                response = _call_once(graph, client, request, service)
                print(f"response:\n{response!r}\n", flush=True)
                while time.monotonic() - started < period:
                    graph.spin_once(min(0.1, max(0.0, period - (time.monotonic() - started))))
        return None  # Ctrl-C: the normal end of a repeated call
    if ros1_output:
        response = graph.call(client, request, f"cannot call '{service}'")
        graph.finish()
        print(message_to_yaml(response))
        return response
    response = _call_once(graph, client, request, service, finish=True)
    print(f"response:\n{response!r}\n")
    return response


def _call_once(graph: Graph, client: Any, request: Any, service: str, finish: bool = False) -> Any:
    print(f"requester: making request: {request!r}\n", flush=True)
    response = graph.call(client, request, f"cannot call '{service}'")
    if finish:
        graph.finish()
    return response


def _wait_until_offered(graph: Graph, service: str, quiet: bool) -> str:
    """The service's type once a server offers it; says it waits (as `ros2 service call`)
    when none is seen at once."""
    if not quiet:
        try:
            return graph.wait_for(
                lambda: service_types(graph, include_hidden=True).get(service),
                "",
                timeout=QUIET_WAIT,
            )[0]
        except ToolError:
            print(WAITING, flush=True)
    return _wait_for_types(graph, service)[0]


# `ros2 service echo`: the events as rosidl_runtime_py converts messages (ros2cli's echo).


def event_text(
    event: Any,
    *,
    csv: bool = False,
    truncate_length: int | None = DEFAULT_TRUNCATE_LENGTH,
    no_arr: bool = False,
    no_str: bool = False,
    flow_style: bool = False,
) -> str:
    """One service event as `ros2 service echo` prints it: YAML with the event type's name,
    then ``---``; or with csv one line of values."""
    options = {"truncate_length": truncate_length, "no_arr": no_arr, "no_str": no_str}
    if csv:
        return message_to_csv(event, **options)
    data = message_to_ordered(event, **options)
    info_data = data.get("info")
    if isinstance(info_data, dict) and "event_type" in info_data:
        info_data["event_type"] = EVENT_TYPES.get(info_data["event_type"], info_data["event_type"])
    text = yaml.dump(
        data,
        Dumper=MessageDumper,
        allow_unicode=True,
        width=sys.maxsize,
        default_flow_style=flow_style,
    )
    return text + "---"


def echo(
    graph: Graph,
    service: str,
    type_name: str | None = None,
    **options: Any,
) -> None:
    """Print the service's introspection events until Ctrl-C (options: see event_text)."""
    service = absolute_name(service)
    with until_stopped():
        if type_name is None:
            type_name = _wait_for_types(graph, service)[0]
        event_type = load_type(type_name, ("srv",)).Event
        topic = service + EVENT_SUFFIX
        received: deque = deque()
        subscription = graph.node.create_subscription(
            event_type, topic, lambda event: received.append(event), qos_profile_services_default
        )
        graph.settle()  # the clients and servers that publish events, if any runs
        if subscription.get_publisher_count() < 1:
            print(
                f"No publishers on topic '{topic}'; "
                "is service introspection on the client or server enabled?",
                flush=True,
            )
        while True:
            while received:
                print(event_text(received.popleft(), **options), flush=True)
            graph.spin_once(0.1)


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("service", help="Various service related sub-commands")
    # As ros2cli: before the sub-command too (`ros2 service --include-hidden-services list`).
    parser.add_argument(
        "--include-hidden-services",
        dest="hidden_before",
        action="store_true",
        help="Consider hidden services as well",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    def hidden(p: argparse.ArgumentParser) -> None:
        p.add_argument(
            "--include-hidden-services",
            action="store_true",
            help="Consider hidden services as well",
        )

    def count(p: argparse.ArgumentParser) -> None:
        p.add_argument(
            "-c",
            "--count-services",
            action="store_true",
            help="Only display the number of services discovered",
        )

    def with_hidden(a: argparse.Namespace) -> bool:
        return a.hidden_before or getattr(a, "include_hidden_services", False)

    p = sub.add_parser("list", parents=[common], help="Output a list of available services")
    p.add_argument(
        "-t", "--show-types", action="store_true", help="Additionally show the service type"
    )
    count(p)
    hidden(p)
    p.set_defaults(
        daemon=True,
        run=lambda graph, a: list_services(graph, a.show_types, a.count_services, with_hidden(a)),
    )

    p = sub.add_parser("type", parents=[common], help="Output a service's type")
    p.add_argument("service_name", help="Name of the ROS service (e.g. '/clear')")
    hidden(p)
    p.set_defaults(run=lambda graph, a: print_type(graph, a.service_name, with_hidden(a)))

    p = sub.add_parser(
        "find", parents=[common], help="Output a list of available services of a given type"
    )
    p.add_argument("service_type", help="Name of the ROS service type (e.g. 'std_srvs/srv/Empty')")
    count(p)
    hidden(p)
    p.set_defaults(
        daemon=True,
        run=lambda graph, a: find(graph, a.service_type, a.count_services, with_hidden(a)),
    )

    p = sub.add_parser("info", parents=[common], help="Print information about a service")
    p.add_argument("service_name", help="Name of the ROS service (e.g. '/add_two_ints')")
    p.add_argument("-v", "--verbose", action="store_true", help="also name the nodes")
    hidden(p)
    p.set_defaults(run=lambda graph, a: info(graph, a.service_name, a.verbose, with_hidden(a)))

    p = sub.add_parser("call", parents=[common], help="Call a service")
    p.add_argument("service_name", help="Name of the ROS service to call (e.g. '/add_two_ints')")
    p.add_argument("service_type", help="Type of the ROS service (e.g. 'std_srvs/srv/Empty')")
    group = p.add_mutually_exclusive_group()
    group.add_argument(
        "values",
        nargs="?",
        default="{}",
        help="Values to fill the service request with in YAML format (e.g. '{a: 1, b: 2}')",
    )
    group.add_argument("--stdin", action="store_true", help="Read values from standard input")
    p.add_argument(
        "-r", "--rate", metavar="N", type=positive_rate, help="Repeat the call at a rate in Hz"
    )
    p.set_defaults(run=_call_command)

    p = sub.add_parser("echo", parents=[common], help="Echo a service")
    p.add_argument("service_name", help="Name of the ROS service to echo (e.g. '/add_two_ints')")
    p.add_argument(
        "service_type",
        nargs="?",
        help="Type of the ROS service (e.g. 'example_interfaces/srv/AddTwoInts')",
    )
    p.add_argument("--csv", action="store_true", help="Output all fields separated by commas")
    p.add_argument(
        "--full-length",
        "-f",
        action="store_true",
        help="Output all elements of arrays, bytes and strings (else cut after --truncate-length)",
    )
    p.add_argument(
        "--truncate-length",
        "-l",
        type=_unsigned_int,
        default=DEFAULT_TRUNCATE_LENGTH,
        help=f"The length to truncate arrays, bytes, and string to (default: "
        f"{DEFAULT_TRUNCATE_LENGTH})",
    )
    p.add_argument("--no-arr", action="store_true", help="Don't print array fields of messages")
    p.add_argument("--no-str", action="store_true", help="Don't print string fields of messages")
    p.add_argument(
        "--flow-style", action="store_true", help="Print sequences in the flow style ([a, b])"
    )
    p.set_defaults(run=_echo_command)


def _unsigned_int(text: str) -> int:
    """An argparse type for a length: a whole number of at least 0."""
    if not text.strip().isdigit():
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number of at least 0")
    return int(text)


def _call_command(graph: Graph, a: argparse.Namespace) -> None:
    text = sys.stdin.read() if a.stdin else a.values
    period = 1.0 / a.rate if a.rate else None
    call(graph, a.service_name, a.service_type, parse_yaml(text), period=period)


def _echo_command(graph: Graph, a: argparse.Namespace) -> None:
    echo(
        graph,
        a.service_name,
        a.service_type,
        csv=a.csv,
        truncate_length=None if a.full_length else a.truncate_length,
        no_arr=a.no_arr,
        no_str=a.no_str,
        flow_style=a.flow_style,
    )
