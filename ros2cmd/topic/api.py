"""What `ros2 topic`'s sub-verbs (verb/) and ROS 1's rostopic (ros1/rostopic.py) share: the
topics and their types, subscribing once a topic is known, the rate arithmetic, --filter, the
warning about a topic of another type, and the options every sub-verb takes."""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections import deque
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

from ros2cmd.errors import ToolError
from ros2cmd.graph import DEFAULT_TIMEOUT, MAX_SETTLE_TIME, Graph, absolute_name, is_hidden
from ros2cmd.typenames import full_type_name, load_type
from ros_tutorials_common.cli import positive_seconds

if TYPE_CHECKING:
    from rclpy.publisher import Publisher

HZ_WINDOW = 10000  # messages, as ros2topic hz and delay


def names_and_types(graph: Graph, hidden: bool = False) -> dict[str, list[str]]:
    """Every topic and its types; names with a part starting with '_' only if hidden."""
    return {
        name: types
        for name, types in graph.node.get_topic_names_and_types()
        if hidden or not is_hidden(name)
    }


def wait_for_types(graph: Graph, topic: str) -> list[str]:
    """The topic's types, once it is in the graph (hidden ones too); ToolError after --timeout."""
    return graph.wait_for(
        lambda: names_and_types(graph, hidden=True).get(topic),
        f"unknown topic '{topic}': no publisher or subscriber seen",
    )


def single_type(graph: Graph, topic: str, type_name: str | None) -> type:
    """The message class to subscribe with: the one given, else the topic's only type."""
    if type_name is not None:
        return load_type(type_name, ("msg",))
    return load_type(_only_type(topic, wait_for_types(graph, topic)), ("msg",))


def _only_type(topic: str, types: list[str]) -> str:
    if len(types) > 1:
        raise ToolError(
            f"Cannot echo topic '{topic}', as it contains more than one type: [{', '.join(types)}]"
        )
    return types[0]


def subscribe_when_known(graph: Graph, topic: str, callback: Callable, raw: bool) -> type:
    """hz, bw and delay: once the topic is in the graph, subscribe as ros2topic does
    (sensor-data QoS, which hears reliable and best-effort publishers alike)."""
    topic = absolute_name(topic)
    try:
        types = wait_for_types(graph, topic)
    except ToolError:
        print(f"WARNING: topic [{topic}] does not appear to be published yet", flush=True)
        types = graph.wait_for(
            lambda: names_and_types(graph, hidden=True).get(topic), "", timeout=math.inf
        )
    from rclpy.qos import qos_profile_sensor_data

    msg_type = load_type(_only_type(topic, types), ("msg",))
    graph.node.create_subscription(msg_type, topic, callback, qos_profile_sensor_data, raw=raw)
    return msg_type


def node_names_known(graph: Graph, topic: str) -> bool:
    """Whether every endpoint of the topic has its node's name yet (endpoints are discovered
    before the names of their nodes)."""
    endpoints = [
        *graph.node.get_publishers_info_by_topic(topic),
        *graph.node.get_subscriptions_info_by_topic(topic),
    ]
    return all(not e.node_name.startswith("_NODE_NAME_UNKNOWN") for e in endpoints)


def publish_one(graph: Graph, publisher: Publisher, msg: Any) -> None:
    from rclpy.executors import ExternalShutdownException

    from ros_tutorials_common.ros import RCLError

    try:
        publisher.publish(msg)
    except RCLError:
        # SIGTERM shut ROS down between two spins (at -r 1e9 the loop never spins): that is
        # the end of the command, as it is when a spin notices it, not an error.
        if not graph.node.context.ok():
            raise ExternalShutdownException() from None
        raise


def filter_expression(expression: str | None) -> Callable[[Any], bool] | None:
    """--filter 'm.data > 2': a Python expression of the message m, as ros2topic has it."""
    if expression is None:
        return None
    try:
        code = compile(expression, "--filter", "eval")
    except SyntaxError as error:
        raise ToolError(f"--filter {expression!r}: {error.msg}") from None

    def keep(m: Any) -> bool:
        try:
            return bool(eval(code, {}, {"m": m}))  # the user's own expression, as ros2topic
        except Exception as error:
            raise ToolError(f"--filter {expression!r}: {type(error).__name__}: {error}") from None

    return keep


def every_second(graph: Graph) -> Iterator[None]:
    """Spins the graph, and comes back once a second (bw's and delay's reports), for ever."""
    next_report = time.monotonic() + 1.0
    while True:
        graph.spin_once(min(0.1, max(0.0, next_report - time.monotonic())))
        if time.monotonic() >= next_report:
            next_report += 1.0
            yield


class OtherType:
    """Says once, on stderr, that a topic carries other types than the one given: ros2cli
    then waits or prints nothing, for ever and without a word (a typed type is easily wrong)."""

    def __init__(self, graph: Graph, topic: str, msg_type: type) -> None:
        self.graph, self.topic, self.type_name = graph, topic, full_type_name(msg_type)
        self.said = False
        self.next_look = time.monotonic() + 0.5  # discovery first

    def look(self) -> None:
        if self.said or time.monotonic() < self.next_look:
            return
        self.next_look = time.monotonic() + 1.0
        node = self.graph.node
        endpoints = [
            *node.get_publishers_info_by_topic(self.topic),
            *node.get_subscriptions_info_by_topic(self.topic),
        ]
        own = (node.get_name(), node.get_namespace())
        types = sorted({e.topic_type for e in endpoints if (e.node_name, e.node_namespace) != own})
        if types and self.type_name not in types:
            self.said = True
            print(
                f"warning: {self.topic} carries {', '.join(types)}, not {self.type_name}: "
                f"nothing there will match (`ros2 topic type {self.topic}` says its type)",
                file=sys.stderr,
                flush=True,
            )


class HzMeter:
    """ros2topic hz's arithmetic: intervals between arrivals, in nanoseconds."""

    def __init__(self, window: int) -> None:
        self.intervals: deque[int] = deque(maxlen=window)
        self.first = -1  # arrival of the first message
        self.last = 0  # arrival of the latest message
        self.last_printed = 0
        self.keep: Callable[[Any], bool] | None = None

    def add(self, msg: Any) -> None:
        if self.keep is not None and not self.keep(msg):
            return
        now = time.time_ns()
        if self.first < 0 or self.first > now:  # the first, or the clock went back
            self.first = self.last = now
            self.intervals.clear()
            return
        self.intervals.append(now - self.last)
        self.last = now

    def report(self) -> str | None:
        """ros2topic hz's rule: once a second of new messages has arrived since the last
        report, the statistics; otherwise nothing (after the publisher stops, nothing new)."""
        if not self.intervals:
            return None
        if self.last_printed == 0:
            self.last_printed = self.last
            return None
        if self.last < self.last_printed + 1_000_000_000:
            return None
        self.last_printed = self.last
        return self.statistics(len(self.intervals))

    def statistics(self, window: int) -> str:
        n = len(self.intervals)
        mean = sum(self.intervals) / n
        rate = 1.0 / mean if mean > 0 else 0.0
        std_dev = math.sqrt(sum((x - mean) ** 2 for x in self.intervals) / n)
        return (
            f"average rate: {rate * 1e9:.3f}\n\tmin: {min(self.intervals) * 1e-9:.3f}s "
            f"max: {max(self.intervals) * 1e-9:.3f}s std dev: {std_dev * 1e-9:.5f}s "
            f"window: {window}"
        )


def nonnegative_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer of 0 or more")
    return value


class _GivenAction(argparse.Action):
    """Stores the value and notes that the option was given (echo's --timeout)."""

    def __call__(self, parser, namespace, values, option_string=None) -> None:
        setattr(namespace, self.dest, values)
        setattr(namespace, f"{self.dest}_given", True)


def add_graph_options(parser: argparse.ArgumentParser, timeout_help: str | None = None) -> None:
    """--spin-time and --timeout (this project's waits), --no-daemon (see daemon/client.py)."""
    parser.add_argument(
        "--spin-time",
        type=positive_seconds,
        help="seconds to wait for discovery (default: until every participant's nodes and "
        f"endpoints are seen, at most {MAX_SETTLE_TIME:g})",
    )
    parser.add_argument(
        "--timeout",
        type=positive_seconds,
        default=DEFAULT_TIMEOUT,
        action=_GivenAction,
        help=timeout_help
        or f"seconds to wait for the topic to appear (default {DEFAULT_TIMEOUT:g})",
    )
    parser.add_argument(
        "--no-daemon", action="store_true", help="Do not spawn nor use an already running daemon"
    )
    parser.set_defaults(timeout_given=False)


def add_hidden_option(parser: argparse.ArgumentParser) -> None:
    """--include-hidden-topics after the sub-verb too; SUPPRESS keeps the value given before
    it (`ros2 topic --include-hidden-topics list`)."""
    parser.add_argument(
        "--include-hidden-topics",
        action="store_true",
        default=argparse.SUPPRESS,
        help="Consider hidden topics as well",
    )
