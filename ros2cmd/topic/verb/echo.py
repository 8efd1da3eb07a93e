"""`ros2 topic echo TOPIC [TYPE]`: each message as YAML and '---', until Ctrl-C; --once the
first one, --timeout N at most N seconds in all."""

from __future__ import annotations

import argparse
import contextlib
import math
import time
from collections import deque
from typing import Any

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.graph import DEFAULT_TIMEOUT, Graph, absolute_name, until_stopped
from ros2cmd.messages import message_to_csv, message_to_yaml
from ros2cmd.qos import AdaptiveSubscription, add_qos_arguments, qos_from_args, qos_overridden
from ros2cmd.topic.api import (
    OtherType,
    add_graph_options,
    add_hidden_option,
    filter_expression,
    nonnegative_int,
    single_type,
)
from ros2cmd.typenames import full_type_name

HELP = "Output messages from a topic"
TRUNCATE_LENGTH = 128  # strings and arrays longer than this end in '...'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    p = parser
    p.add_argument("topic_name", help="Name of the ROS topic to listen to (e.g. '/chatter')")
    p.add_argument(
        "message_type", nargs="?", help="Type of the ROS message (e.g. 'std_msgs/msg/String')"
    )
    add_qos_arguments(p, "subscribe", "sensor_data")
    p.add_argument(
        "--csv", action="store_true", help="Output all recursive fields separated by commas"
    )
    p.add_argument(
        "--field",
        help="Echo a selected field of a message. Use '.' to select sub-fields "
        "(e.g. 'linear.x' of a geometry_msgs/msg/Twist)",
    )
    p.add_argument(
        "--full-length",
        "-f",
        action="store_true",
        help="Output all elements for arrays, bytes, and string with a length > "
        "'--truncate-length', by default they are truncated after '--truncate-length' "
        "elements with '...'",
    )
    p.add_argument(
        "--truncate-length",
        "-l",
        type=nonnegative_int,
        default=TRUNCATE_LENGTH,
        help=f"The length to truncate arrays, bytes, and string to (default: {TRUNCATE_LENGTH})",
    )
    p.add_argument("--no-arr", action="store_true", help="Don't print array fields of messages")
    p.add_argument("--no-str", action="store_true", help="Don't print string fields of messages")
    p.add_argument(
        "--flow-style",
        action="store_true",
        help="Print collections in the block style (not available with csv format)",
    )
    p.add_argument(
        "--no-lost-messages", action="store_true", help="Don't report when a message is lost"
    )
    p.add_argument("--raw", action="store_true", help="Echo the raw binary representation")
    p.add_argument(
        "--filter",
        dest="filter_expr",
        help="Python expression to filter messages that are printed. Expression can use "
        "Python builtins as well as m (the message).",
    )
    p.add_argument(
        "--once", action="store_true", help="Print the first message received and then exit."
    )
    add_hidden_option(p)
    add_graph_options(
        p,
        "Set a timeout in seconds for waiting: for the topic to appear (default "
        f"{DEFAULT_TIMEOUT:g}) and, when given, for messages (then exit)",
    )
    completion.attach(p, topic_name=completion.topic_names, message_type=completion.types_for_topic)


def main(graph: Graph, args: argparse.Namespace) -> None:
    with until_stopped() if not args.once else contextlib.nullcontext():
        _echo(graph, args)


def _echo(graph: Graph, args: argparse.Namespace) -> None:
    from rclpy.event_handler import SubscriptionEventCallbacks

    deadline = time.monotonic() + args.timeout if args.timeout_given else math.inf
    topic = absolute_name(args.topic_name)
    msg_type = single_type(graph, topic, args.message_type)
    echo = _Echo(args, _field_path(msg_type, args.field))
    received: deque = deque()
    lost = None if args.no_lost_messages else _lost_messages

    def on_message(msg: Any) -> None:
        received.append(msg)

    if qos_overridden(args):
        graph.node.create_subscription(
            msg_type,
            topic,
            on_message,
            qos_from_args(args),
            raw=args.raw,
            event_callbacks=SubscriptionEventCallbacks(message_lost=lost),
        )
        subscription = None
    else:  # the QoS that matches the publishers, now and as they come and go
        subscription = AdaptiveSubscription(graph, msg_type, topic, on_message, raw=args.raw)
    other_type = OtherType(graph, topic, msg_type)
    while time.monotonic() < deadline:
        graph.spin_once(min(0.1, max(0.0, deadline - time.monotonic())))
        if args.message_type is not None:
            other_type.look()
        if subscription is not None:
            subscription.update()
        while received:
            text = echo.text(received.popleft())
            if text is None:
                continue
            if args.once:
                graph.finish()
            print(text, flush=True)
            if args.once:
                return
    graph.finish()  # --timeout: the time is up, which ends the command normally


def _field_path(msg_type: type, field: str | None) -> list[str] | None:
    """--field linear.x as names, checked against the type now, not at the first message."""
    if field is None:
        return None
    names = [name for name in field.split(".") if name]
    if not names:
        raise ToolError(f"Invalid field value '{field}'")
    msg: Any = msg_type()
    for name in names:
        fields = list(getattr(msg, "get_fields_and_field_types", dict)())
        if name not in fields:
            what = full_type_name(type(msg)) if fields else f"{type(msg).__name__} value"
            has = f" (fields: {', '.join(fields)})" if fields else ""
            raise ToolError(f"Invalid field '{field}': {what} has no field '{name}'{has}")
        msg = getattr(msg, name)
    return names


class _Echo:
    """What `ros2 topic echo` prints for each message, by its options."""

    def __init__(self, args: argparse.Namespace, fields: list[str] | None) -> None:
        self.args = args
        self.fields = fields
        self.truncate = None if args.full_length else args.truncate_length
        self.filter = filter_expression(args.filter_expr)

    def text(self, msg: Any) -> str | None:
        """The lines for one message, '---' included; None if --filter leaves it out."""
        for name in self.fields or []:
            msg = getattr(msg, name)
        if self.filter is not None and not self.filter(msg):
            return None
        if not hasattr(msg, "get_fields_and_field_types"):  # raw bytes, or a field's value
            return f"{msg}\n---"
        options = {"truncate_length": self.truncate, "no_arr": self.args.no_arr}
        options["no_str"] = self.args.no_str
        if self.args.csv:
            return message_to_csv(msg, **options)
        return message_to_yaml(msg, flow_style=self.args.flow_style, **options) + "\n---"


def _lost_messages(status: Any) -> None:
    print(
        "A message was lost!!!\n\ttotal count change:"
        f"{status.total_count_change}\n\ttotal count: {status.total_count}",
        end="---\n",
        flush=True,
    )
