"""`ros2 service echo SERVICE [TYPE]`: what service introspection publishes on
``SERVICE/_service_event`` (service_msgs/msg/ServiceEventInfo and the request or response), as
YAML with the event type's name, once a client or server has it on (``configure_introspection``;
the demo_nodes_cpp introspection demo turns it on by parameter). Messages are converted as
rosidl_runtime_py converts them (ros2cli's echo)."""

from __future__ import annotations

import argparse
import sys
from collections import deque
from typing import Any

from ros2cmd import completion
from ros2cmd.graph import Graph, absolute_name, until_stopped
from ros2cmd.messages import message_dumper, message_to_csv, message_to_ordered
from ros2cmd.service.api import wait_for_types
from ros2cmd.typenames import load_type
from ros_tutorials_common.names import SERVICE_EVENT_SUFFIX

HELP = "Echo a service"
DEFAULT_TRUNCATE_LENGTH = 128  # longer strings and arrays are shortened
EVENT_NAMES = ("REQUEST_SENT", "REQUEST_RECEIVED", "RESPONSE_SENT", "RESPONSE_RECEIVED")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    p = parser
    p.add_argument("service_name", help="Name of the ROS service to echo (e.g. '/add_two_ints')")
    completion.attach(p, service_name=completion.service_names)
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


def _unsigned_int(text: str) -> int:
    """An argparse type for a length: a whole number of at least 0."""
    if not text.strip().isdigit():
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number of at least 0")
    return int(text)


def main(graph: Graph, args: argparse.Namespace) -> None:
    """Print the service's introspection events until Ctrl-C."""
    service = absolute_name(args.service_name)
    options = {
        "csv": args.csv,
        "truncate_length": None if args.full_length else args.truncate_length,
        "no_arr": args.no_arr,
        "no_str": args.no_str,
        "flow_style": args.flow_style,
    }
    from rclpy.qos import qos_profile_services_default

    with until_stopped():
        type_name = args.service_type
        if type_name is None:
            type_name = wait_for_types(graph, service)[0]
        event_type = load_type(type_name, ("srv",)).Event
        topic = service + SERVICE_EVENT_SUFFIX
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
    from service_msgs.msg import ServiceEventInfo

    event_types = {getattr(ServiceEventInfo, name): name for name in EVENT_NAMES}
    options = {"truncate_length": truncate_length, "no_arr": no_arr, "no_str": no_str}
    if csv:
        return message_to_csv(event, **options)
    data = message_to_ordered(event, **options)
    info_data = data.get("info")
    if isinstance(info_data, dict) and "event_type" in info_data:
        info_data["event_type"] = event_types.get(info_data["event_type"], info_data["event_type"])
    import yaml

    text = yaml.dump(
        data,
        Dumper=message_dumper(),
        allow_unicode=True,
        width=sys.maxsize,
        default_flow_style=flow_style,
    )
    return text + "---"
