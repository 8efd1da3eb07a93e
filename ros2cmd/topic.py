"""`ros2 topic ...`: list, echo, pub, hz, bw, info, type and find topics (like `ros2 topic`)."""

from __future__ import annotations

import argparse
import contextlib
import statistics
import sys
import time
from collections import deque
from itertools import pairwise
from typing import Any

import yaml
from rclpy.duration import Duration
from rclpy.executors import ExternalShutdownException
from rclpy.publisher import Publisher
from rclpy.qos import DurabilityPolicy, QoSProfile

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name, add_list_and_type, print_names, until_stopped
from ros2cmd.messages import fill_message, message_to_data, message_to_yaml, parse_yaml
from ros2cmd.qos import AdaptiveSubscription
from ros2cmd.qos import compatible_qos as compatible_qos  # moved to qos.py; kept importable
from ros2cmd.typenames import full_type_name, load_type
from ros_tutorials_common.cli import positive_int, positive_rate
from ros_tutorials_common.ros import RCLError

DEFAULT_PUB_RATE = 1.0  # Hz, as `ros2 topic pub`


def list_topics(graph: Graph, show_types: bool = False) -> None:
    print_names(graph, graph.topic_types, show_types)


def print_type(graph: Graph, topic: str) -> None:
    print(graph.wait_for_topic_type(absolute_name(topic)))


def find(graph: Graph, type_name: str) -> None:
    wanted = full_type_name(load_type(type_name, ("msg",)))  # an unknown type: an error first
    print_names(graph, graph.topic_types, of_type=wanted)


TYPES_DO_NOT_TALK = (
    "note: this topic carries several types; publishers and subscribers of different "
    "types do not talk to each other"
)


def info(graph: Graph, topic: str, verbose: bool = False) -> None:
    topic = absolute_name(topic)
    graph.wait_for_topic_type(topic)
    # The first endpoint seen makes the topic known; let every other one arrive too (one of
    # another type, an AandB talker beside a String listener, is the one a learner needs).
    graph.settle()
    if verbose:
        # Endpoints are discovered before the names of their nodes: wait for those too.
        with contextlib.suppress(ToolError):  # after --timeout, print what is known
            graph.wait_for(lambda: _node_names_known(graph, topic), "")
    publishers = graph.node.get_publishers_info_by_topic(topic)
    subscriptions = graph.node.get_subscriptions_info_by_topic(topic)
    types = sorted(
        {e.topic_type for e in (*publishers, *subscriptions)}
        | set(graph.topic_types().get(topic, []))
    )
    for type_name in types:  # one line each, as `ros2 topic info` when there are several
        print(f"Type: {type_name}")
    if len(types) > 1:
        print(TYPES_DO_NOT_TALK)
    for title, endpoints in (("Publisher", publishers), ("Subscription", subscriptions)):
        print(f"{title} count: {len(endpoints)}")
        if not verbose:
            continue
        for endpoint in endpoints:
            qos = endpoint.qos_profile
            print(f"  Node: {endpoint.node_namespace.rstrip('/')}/{endpoint.node_name}")
            if len(types) > 1:
                print(f"    Topic type: {endpoint.topic_type}")
            print(f"    Reliability: {qos.reliability.name}, Durability: {qos.durability.name}")


def _node_names_known(graph: Graph, topic: str) -> bool:
    endpoints = [
        *graph.node.get_publishers_info_by_topic(topic),
        *graph.node.get_subscriptions_info_by_topic(topic),
    ]
    return all(not e.node_name.startswith("_NODE_NAME_UNKNOWN") for e in endpoints)


def _message_type(graph: Graph, topic: str, type_name: str | None) -> type:
    return load_type(type_name or graph.wait_for_topic_type(topic), ("msg",))


def _pick_field(data: object, field: str) -> object:
    """`--field stamp.sec`: walk into the message data one field at a time."""
    for name in field.split("."):
        if not isinstance(data, dict) or name not in data:
            raise ToolError(f"the message has no field '{field}'")
        data = data[name]
    return data


def topic_and_field(graph: Graph, name: str) -> tuple[str, str | None]:
    """ROS 1's `rostopic echo /topic/field`: a name that is not a topic but starts with one
    names a field of it ('/ros_tutorial_msg/stamp/sec' -> '/ros_tutorial_msg', 'stamp.sec').

    Waits (up to --timeout) for the topic or a topic that starts the name.
    """
    name = absolute_name(name).rstrip("/") or "/"
    parts = name.split("/")

    def find() -> tuple[str, str | None] | None:
        topics = graph.topic_types()
        if name in topics:
            return name, None
        for end in range(len(parts) - 1, 1, -1):  # the longest topic first
            if "/".join(parts[:end]) in topics:
                return "/".join(parts[:end]), ".".join(parts[end:])
        return None

    found = graph.wait_for(find, f"unknown topic '{name}': no publisher or subscriber seen")
    if found[1] is not None:
        graph.settle()  # a topic of the whole name may be running, not yet discovered
        found = find() or found
    return found


def echo(
    graph: Graph,
    topic: str,
    type_name: str | None = None,
    count: int | None = None,
    field: str | None = None,
    field_in_name: bool = False,
) -> None:
    """Print messages as YAML, each followed by '---'; `count` of them, or until Ctrl-C.

    Only `field` of each (`--field stamp.sec`), or with field_in_name the field the name
    selects as in ROS 1 (`/ros_tutorial_msg/stamp/sec`, see topic_and_field).
    With a count it is a one-shot command: Ctrl-C before the last message is "interrupted".
    """
    with until_stopped() if count is None else contextlib.nullcontext():
        if field_in_name:
            topic, field = topic_and_field(graph, topic)
        _echo(graph, absolute_name(topic), type_name, count, field)


def _echo(
    graph: Graph, topic: str, type_name: str | None, count: int | None, field: str | None
) -> None:
    msg_type = _message_type(graph, topic, type_name)
    if field is not None:  # a field the type does not have: say so now, not at a message
        try:
            _pick_field(message_to_data(msg_type()), field)
        except ToolError:
            raise ToolError(f"{full_type_name(msg_type)} has no field '{field}'") from None
    received: deque = deque()
    # rclpy inspects the callback's signature, which a bound builtin like deque.append lacks.
    subscription = AdaptiveSubscription(graph, msg_type, topic, lambda msg: received.append(msg))
    printed = 0
    while True:
        graph.spin_once(0.1)
        subscription.update()
        while received:
            msg = received.popleft()
            if printed + 1 == count:
                graph.finish()
            if field is None:
                print(message_to_yaml(msg))
            else:
                value = _pick_field(message_to_data(msg), field)
                print(_field_text(value))
            print("---", flush=True)
            printed += 1
            if printed == count:
                return


def _field_text(value: object) -> str:
    if isinstance(value, (dict, list)):
        return yaml.safe_dump(value, default_flow_style=False, sort_keys=False).rstrip()
    return str(value)


def pub(
    graph: Graph,
    topic: str,
    type_name: str,
    values: Any = None,
    rate: float | None = DEFAULT_PUB_RATE,
    times: int | None = None,
    latch: bool = False,
    verbose: bool = True,
) -> None:
    """Publish a message filled from values: `times` times (None: until Ctrl-C) at `rate` Hz,
    printing each message unless not verbose (ROS 1's `rostopic pub -r` printed none).

    rate=None publishes once and keeps the publisher alive until Ctrl-C (ROS 1's latching
    mode, with a transient-local publisher so late subscribers that ask for it still get it).
    """
    topic = absolute_name(topic)
    msg_type = load_type(type_name, ("msg",))
    msg = fill_message(msg_type(), values)
    qos = QoSProfile(depth=10)
    if latch:
        qos.durability = DurabilityPolicy.TRANSIENT_LOCAL
    if rate is None or times is None:
        # Runs until Ctrl-C, as echo and hz do: from here on, Ctrl-C is its normal end. The
        # lines below that say so are printed inside, never just before (see until_stopped).
        with until_stopped():
            publisher = graph.node.create_publisher(msg_type, topic, qos)
            if rate is None:
                print("publishing and latching message. Press ctrl-C to terminate", flush=True)
                _latch(graph, publisher, msg)
            else:
                _publish(graph, publisher, msg, rate, times, verbose)
        return
    publisher = graph.node.create_publisher(msg_type, topic, qos)
    # A one-shot publication into a void is lost: give subscribers time to match first.
    try:
        graph.wait_for(publisher.get_subscription_count, "no subscriber")
    except ToolError:
        print(f"warning: {_why_no_subscriber(graph, topic, msg_type)}", file=sys.stderr)
    _publish(graph, publisher, msg, rate, times, verbose)  # Ctrl-C before the last: interrupted
    # Reliable delivery of the last message before the process goes away.
    publisher.wait_for_all_acked(Duration(seconds=graph.timeout))


def _why_no_subscriber(graph: Graph, topic: str, msg_type: type) -> str:
    """No subscriber matched: say if those on the topic want another type (they never will).

    ROS 1's rostopic published anyway (the subscriber refused the connection); so does this.
    """
    ours = full_type_name(msg_type)
    others = sorted(
        {s.topic_type for s in graph.node.get_subscriptions_info_by_topic(topic)} - {ours}
    )
    if others:
        return (
            f"{topic} carries {', '.join(others)}, not {ours}: the message will not reach "
            "its subscribers; publishing anyway"
        )
    return f"no subscriber on {topic}; publishing anyway"


def _latch(graph: Graph, publisher: Publisher, msg: Any) -> None:
    served = 0
    while True:
        # ROS 1 latching: every subscriber that joins gets the message. A ROS 2 volatile
        # subscription would miss one sent before it matched, so send it again on each join.
        subscribers = publisher.get_subscription_count()
        if subscribers > served:
            _publish_one(graph, publisher, msg)
        served = subscribers
        graph.spin_once(0.1)


def _publish_one(graph: Graph, publisher: Publisher, msg: Any) -> None:
    try:
        publisher.publish(msg)
    except RCLError:
        # SIGTERM shut ROS down between two spins (at -r 1e9 the loop never spins): that is
        # the end of the command, as it is when a spin notices it, not an error.
        if not graph.node.context.ok():
            raise ExternalShutdownException() from None
        raise


def _publish(
    graph: Graph, publisher: Publisher, msg: Any, rate: float, times: int | None, verbose: bool
) -> None:
    if verbose:
        print("publisher: beginning loop", flush=True)
    count = 0
    next_time = time.monotonic()
    while times is None or count < times:
        wait = next_time - time.monotonic()
        if wait > 0:
            graph.spin_once(min(wait, 0.1))
            continue
        count += 1
        _publish_one(graph, publisher, msg)
        if verbose:
            print(f"publishing #{count}: {msg}", flush=True)
        next_time += 1.0 / rate


class _RateMeter:
    """Arrival times in a sliding window, and the statistics `hz` prints."""

    def __init__(self, window: int) -> None:
        self.times: deque[float] = deque(maxlen=window + 1)
        self.sizes: deque[int] = deque(maxlen=window)

    def add(self, raw: bytes) -> None:
        self.times.append(time.monotonic())
        self.sizes.append(len(raw))

    def periods(self) -> list[float]:

        return [b - a for a, b in pairwise(self.times)]


def hz(graph: Graph, topic: str, window: int = 10000, bandwidth: bool = False) -> None:
    """Print the publishing rate (or bandwidth) of a topic once a second until Ctrl-C."""
    with until_stopped():
        _hz(graph, absolute_name(topic), window, bandwidth)


def _hz(graph: Graph, topic: str, window: int, bandwidth: bool) -> None:
    msg_type = _message_type(graph, topic, None)
    meter = _RateMeter(window)
    # raw=True: count serialized messages without the cost of deserializing them.
    subscription = AdaptiveSubscription(graph, msg_type, topic, meter.add, raw=True)
    print(f"subscribed to [{topic}]", flush=True)
    last_report = time.monotonic()
    while True:
        graph.spin_once(0.1)
        subscription.update()
        if time.monotonic() - last_report < 1.0:
            continue
        last_report = time.monotonic()
        periods = meter.periods()
        if not periods:
            print("no new messages", flush=True)
            continue
        mean = statistics.fmean(periods)
        if bandwidth:
            rate = sum(meter.sizes) / (meter.times[-1] - meter.times[0] or 1.0)
            print(f"{rate:.2f} B/s from {len(meter.sizes)} messages", flush=True)
            print(f"\tMessage size mean: {statistics.fmean(meter.sizes):.0f} B", flush=True)
            continue
        print(f"average rate: {1.0 / mean:.3f}", flush=True)
        std = statistics.pstdev(periods)
        print(
            f"\tmin: {min(periods):.3f}s max: {max(periods):.3f}s "
            f"std dev: {std:.5f}s window: {len(periods) + 1}",
            flush=True,
        )


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("topic", help="topics: list, echo, pub, hz, bw, info, type, find")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    add_list_and_type(sub, common, "topic", list_topics, print_type)

    p = sub.add_parser("echo", parents=[common], help="print the messages on a topic")
    p.add_argument("topic")
    p.add_argument("type", nargs="?", help="message type (default: the one in the graph)")
    p.add_argument("--once", action="store_true", help="print one message and exit")
    p.add_argument("--field", help="print only this field, e.g. stamp.sec")
    p.set_defaults(
        run=lambda graph, a: echo(graph, a.topic, a.type, 1 if a.once else None, a.field)
    )

    p = sub.add_parser("pub", parents=[common], help="publish a message given as YAML")
    p.add_argument("topic")
    p.add_argument("type", help="message type, e.g. std_msgs/msg/String")
    p.add_argument("values", nargs="?", default="{}", help="the fields as YAML, e.g. '{data: hi}'")
    group = p.add_mutually_exclusive_group()  # --once is "one message now": no rate, no count
    group.add_argument("-1", "--once", action="store_true", help="publish one message, then exit")
    group.add_argument("-r", "--rate", type=positive_rate, help="Hz (default 1)")
    p.add_argument("-t", "--times", type=positive_int, help="publish this many messages, then exit")
    p.set_defaults(run=lambda graph, a, parser=p: _pub_command(graph, a, parser))

    for name, bandwidth in (("hz", False), ("bw", True)):
        what = "bandwidth" if bandwidth else "publishing rate"
        p = sub.add_parser(name, parents=[common], help=f"print the {what} of a topic")
        p.add_argument("topic")
        p.add_argument(
            "-w", "--window", type=positive_int, default=10000, help="messages to average"
        )
        p.set_defaults(run=lambda graph, a, bw=bandwidth: hz(graph, a.topic, a.window, bw))

    p = sub.add_parser("info", parents=[common], help="type, publishers and subscriptions")
    p.add_argument("topic")
    p.add_argument("-v", "--verbose", action="store_true", help="list the endpoints")
    p.set_defaults(run=lambda graph, a: info(graph, a.topic, a.verbose))

    p = sub.add_parser("find", parents=[common], help="list the topics of a message type")
    p.add_argument("type")
    p.set_defaults(daemon=True, run=lambda graph, a: find(graph, a.type))


def _pub_command(graph: Graph, args: argparse.Namespace, parser: argparse.ArgumentParser) -> None:
    if args.once and args.times is not None:
        parser.error("argument -t/--times: not allowed with argument -1/--once")
    times = 1 if args.once else args.times
    rate = DEFAULT_PUB_RATE if args.rate is None else args.rate
    pub(graph, args.topic, args.type, parse_yaml(args.values), rate, times)
