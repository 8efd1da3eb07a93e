"""`ros2 service call SERVICE TYPE VALUES [-r RATE]`: the request and the response as Python
writes them (``requester: making request: turtlesim.srv.Spawn_Request(...)``, a blank line,
``response:``, ``turtlesim.srv.Spawn_Response(name='turtle2')``)."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name, until_stopped
from ros2cmd.messages import fill_message, parse_yaml
from ros2cmd.service.api import service_types, wait_for_types
from ros2cmd.typenames import full_type_name, load_type
from ros_tutorials_common.cli import positive_rate

HELP = "Call a service"
WAITING = "waiting for service to become available..."
# How long `call` looks for the service before it says it is waiting (discovery usually
# finds a running server within a few hundred milliseconds).
QUIET_WAIT = 1.0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    p = parser
    p.add_argument("service_name", help="Name of the ROS service to call (e.g. '/add_two_ints')")
    p.add_argument("service_type", help="Type of the ROS service (e.g. 'std_srvs/srv/Empty')")
    completion.attach(
        p, service_name=completion.service_names, service_type=completion.types_for_service
    )
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


def main(graph: Graph, args: argparse.Namespace) -> None:
    text = sys.stdin.read() if args.stdin else args.values
    period = 1.0 / args.rate if args.rate else None
    call(graph, args.service_name, args.service_type, parse_yaml(text), period=period)


def call(
    graph: Graph, service: str, type_name: str | None, values: Any, period: float | None = None
) -> None:
    """Call a service with a request filled from `values` (a dict, or a list in field order).
    With a period, calls again every period seconds until Ctrl-C."""
    service = absolute_name(service)
    srv_type = load_type(type_name, ("srv",)) if type_name else None
    request = fill_message(srv_type.Request(), values) if srv_type else None  # check input first
    offered = _wait_until_offered(graph, service)
    if srv_type is None:
        srv_type = load_type(offered, ("srv",))
        request = fill_message(srv_type.Request(), values)
    elif full_type_name(srv_type) != offered:
        raise ToolError(f"service '{service}' has type {offered}, not {full_type_name(srv_type)}")
    client = graph.node.create_client(srv_type, service)
    if period is None:
        response = _call_once(graph, client, request, service, finish=True)
        print(f"response:\n{response!r}\n")
        return
    with until_stopped():  # Ctrl-C: the normal end of a repeated call
        while True:
            started = time.monotonic()
            response = _call_once(graph, client, request, service)
            print(f"response:\n{response!r}\n", flush=True)
            while time.monotonic() - started < period:
                graph.spin_once(min(0.1, max(0.0, period - (time.monotonic() - started))))


def _call_once(graph: Graph, client: Any, request: Any, service: str, finish: bool = False) -> Any:
    print(f"requester: making request: {request!r}\n", flush=True)
    response = graph.call(client, request, f"cannot call '{service}'")
    if finish:
        graph.finish()
    return response


def _wait_until_offered(graph: Graph, service: str) -> str:
    """The service's type once a server offers it; says it waits (as `ros2 service call`)
    when none is seen at once."""
    try:
        return graph.wait_for(
            lambda: service_types(graph, include_hidden=True).get(service),
            "",
            timeout=QUIET_WAIT,
        )[0]
    except ToolError:
        print(WAITING, flush=True)
    return wait_for_types(graph, service)[0]
