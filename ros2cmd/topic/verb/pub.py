"""`ros2 topic pub TOPIC TYPE VALUES`: at --rate Hz until Ctrl-C, or --times / --once.

Waits for -w matching subscriptions first (1 with --once or --times), saying so every second,
as ros2topic does; with --max-wait-time-secs at most that long.
"""

from __future__ import annotations

import argparse
import contextlib
import time
from typing import TYPE_CHECKING

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name, until_stopped
from ros2cmd.messages import fill_message, parse_yaml
from ros2cmd.qos import add_qos_arguments, qos_from_args
from ros2cmd.topic.api import OtherType, add_graph_options, nonnegative_int, publish_one
from ros2cmd.typenames import load_type
from ros_tutorials_common.bounded import InputError, read_text
from ros_tutorials_common.cli import positive_rate, positive_seconds
from ros_tutorials_common.wait import spin_until

if TYPE_CHECKING:
    from rclpy.publisher import Publisher

HELP = "Publish a message to a topic"
WAIT_PERIOD = 0.1  # s between looks for matching subscriptions (-w)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    p = parser
    p.add_argument("topic_name", help="Name of the ROS topic to publish to (e.g. '/chatter')")
    p.add_argument("message_type", help="Type of the ROS message (e.g. 'std_msgs/String')")
    completion.attach(p, topic_name=completion.topic_names, message_type=completion.types_for_topic)
    group = p.add_mutually_exclusive_group()
    group.add_argument(
        "values",
        nargs="?",
        default="{}",
        help="Values to fill the message with in YAML format (e.g. 'data: Hello World'), "
        "otherwise the message will be published with default values",
    )
    group.add_argument("--stdin", action="store_true", help="Read values from standard input")
    p.add_argument(
        "-r",
        "--rate",
        metavar="N",
        type=positive_rate,
        default=1.0,
        help="Publishing rate in Hz (default: 1)",
    )
    p.add_argument(
        "-p",
        "--print",
        metavar="N",
        type=int,
        default=1,
        help="Only print every N-th published message (default: 1)",
    )
    group = p.add_mutually_exclusive_group()
    group.add_argument("-1", "--once", action="store_true", help="Publish one message and exit")
    group.add_argument(
        "-t",
        "--times",
        type=nonnegative_int,
        default=0,
        help="Publish this number of times and then exit",
    )
    p.add_argument(
        "-w",
        "--wait-matching-subscriptions",
        type=nonnegative_int,
        help="Wait until finding the specified number of matching subscriptions. "
        'Defaults to 1 when using "-1"/"--once"/"--times", otherwise defaults to 0.',
    )
    p.add_argument(
        "--max-wait-time-secs",
        type=positive_seconds,
        help="This sets the maximum wait time in seconds if "
        "--wait-until-matching-subscriptions is set. By default, this flag is not set "
        "meaning the subscriber will wait endlessly.",
    )
    p.add_argument(
        "--keep-alive",
        metavar="N",
        type=positive_seconds,
        default=0.1,
        help="Keep publishing node alive for N seconds after the last msg (default: 0.1)",
    )
    add_qos_arguments(p, "publish", "default")
    add_graph_options(p)


def main(graph: Graph, args: argparse.Namespace) -> None:
    from rclpy.duration import Duration

    times = 1 if args.once else args.times
    wait_for = args.wait_matching_subscriptions
    if wait_for is None:
        wait_for = int(times != 0)
    if wait_for == 0 and args.max_wait_time_secs is not None:
        raise ToolError(
            "--max-wait-time-secs option is only effective with "
            "--wait-matching-subscriptions, --once or --times"
        )
    topic = absolute_name(args.topic_name)
    msg_type = load_type(args.message_type, ("msg",))
    try:
        text = read_text("/dev/stdin") if args.stdin else args.values
    except InputError as error:
        raise ToolError(str(error)) from None
    values = parse_yaml(text)
    if not isinstance(values, dict):
        raise ToolError("The passed value needs to be a dictionary in YAML format")
    stamps: list = []  # `header: auto`, `stamp: now`: stamped anew at each publication
    msg = fill_message(msg_type(), values, stamps=stamps)
    with until_stopped() if times == 0 else contextlib.nullcontext():
        publisher = graph.node.create_publisher(msg_type, topic, qos_from_args(args))
        other_type = OtherType(graph, topic, msg_type)
        _wait_for_subscriptions(graph, publisher, wait_for, args.max_wait_time_secs, other_type)
        print("publisher: beginning loop", flush=True)
        count = 0
        next_time = time.monotonic()
        while times == 0 or count < times:
            wait = next_time - time.monotonic()
            if wait > 0:
                graph.spin_once(min(wait, 0.1))
                other_type.look()
                continue
            now = graph.node.get_clock().now().to_msg()
            for stamp in stamps:
                stamp(now)
            count += 1
            if args.print and count % args.print == 0:
                print(f"publishing #{count}: {msg!r}\n", flush=True)
            publish_one(graph, publisher, msg)
            next_time += 1.0 / args.rate
        # Time for the last message to reach the wire (and reliable subscribers) before exit.
        publisher.wait_for_all_acked(Duration(seconds=graph.timeout))
        spin_until(graph.executor, lambda: False, args.keep_alive)


def _wait_for_subscriptions(
    graph: Graph, publisher: Publisher, wanted: int, max_wait: float | None, other_type: OtherType
) -> None:
    waited = 0.0
    since_said = 0
    while publisher.get_subscription_count() < wanted:
        other_type.look()
        if since_said == 0:
            print(f"Waiting for at least {wanted} matching subscription(s)...", flush=True)
        if max_wait is not None and waited >= max_wait:
            raise ToolError(
                f"Timed out waiting for subscribers: Expected {wanted} subcribers but only "
                f"got {publisher.get_subscription_count()} subscribers"
            )
        since_said = (since_said + 1) % 10  # the line again every second
        graph.spin_once(WAIT_PERIOD)
        waited += WAIT_PERIOD
