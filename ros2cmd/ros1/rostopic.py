"""`rostopic list|echo|pub|hz|bw|info|type|find`: ROS 1's rostopic on `ros2 topic`'s api.

    rostopic pub /cmd_vel geometry_msgs/Twist -r 10 '{linear: {x: 1.0}}'    options anywhere
    rostopic echo /turtle1/pose/x                                          one field, by name

Where ROS 1's output or rules differ from ros2topic's they are kept here: `rostopic info`'s
lines, `echo /topic/field`, latching `pub`, `hz`'s print rule and `bw`. See
ros2cmd/ros1/tool.py for what all the ROS 1 tools share.
"""

from __future__ import annotations

import argparse
import contextlib
import statistics
import sys
import time
from collections import deque
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name, print_names, until_stopped
from ros2cmd.messages import fill_message, message_to_data, message_to_yaml
from ros2cmd.qos import AdaptiveSubscription
from ros2cmd.ros1 import tool
from ros2cmd.topic.api import HzMeter, node_names_known, publish_one
from ros2cmd.typenames import full_type_name, load_type
from ros_tutorials_common.cli import positive_int, positive_rate
from ros_tutorials_common.shutdown import program_main

if TYPE_CHECKING:
    from rclpy.publisher import Publisher

DEFAULT_PUB_RATE = 1.0  # Hz
WINDOW = 10000  # messages: hz and bw


def rostopic_parser() -> argparse.ArgumentParser:
    parser, sub, common = tool.new_parser(
        "rostopic", "ROS 1's rostopic, on ROS 2 (see: ros2 topic)"
    )

    p = sub.add_parser("list", parents=[common], help="list topics")
    p.add_argument("-v", "--verbose", action="store_true", help="with types")
    p.set_defaults(
        daemon=True, run=lambda graph, a: print_names(graph, graph.topic_types, a.verbose)
    )

    p = sub.add_parser("echo", parents=[common], help="print messages")
    p.add_argument("topic", help="a topic, or /topic/field for one field (/t/stamp/sec)")
    completion.attach(p, topic=completion.topic_names)
    p.add_argument("-n", type=positive_int, help="print this many messages, then exit")
    p.set_defaults(run=lambda graph, a: echo(graph, a.topic, count=a.n, field_in_name=True))

    p = sub.add_parser("pub", parents=[common], help="publish a message")
    p.add_argument("topic")
    p.add_argument("type")
    p.add_argument("values", nargs="*", help="a YAML mapping, or field values in order")
    completion.attach(p, topic=completion.topic_names, type=completion.ros1_types_for_topic)
    group = p.add_mutually_exclusive_group()  # ROS 1 refused both too
    group.add_argument("-r", "--rate", type=positive_rate, help="publish at this rate until Ctrl-C")
    group.add_argument("-1", "--once", action="store_true", help="publish once, then exit")
    p.add_argument("-v", "--verbose", action="store_true", help="print each message (with -r)")
    p.set_defaults(run=_pub)

    for name, bandwidth in (("hz", False), ("bw", True)):
        p = sub.add_parser(name, parents=[common], help="")
        p.add_argument("topic")
        completion.attach(p, topic=completion.topic_names)
        p.set_defaults(run=lambda graph, a, b=bandwidth: hz(graph, a.topic, WINDOW, b))

    p = sub.add_parser("info", parents=[common], help="publishers etc.")
    p.add_argument("topic")
    completion.attach(p, topic=completion.topic_names)
    p.set_defaults(run=lambda graph, a: info(graph, a.topic, True))

    p = sub.add_parser("type", parents=[common], help="message type")
    p.add_argument("topic")
    completion.attach(p, topic=completion.topic_names)
    p.set_defaults(
        daemon=True,
        run=lambda graph, a: print(graph.wait_for_topic_type(absolute_name(a.topic))),
    )

    p = sub.add_parser("find", parents=[common], help="topics of a type")
    p.add_argument("type")
    completion.attach(p, type=completion.ros1_message_types)
    p.set_defaults(daemon=True, run=lambda graph, a: find(graph, a.type))
    return parser


def _pub(graph: Graph, args: argparse.Namespace) -> None:
    values = tool.values_from_args(args.values)
    if args.rate is not None:
        pub(graph, args.topic, args.type, values, rate=args.rate, verbose=args.verbose)
    elif args.once:
        pub(graph, args.topic, args.type, values, times=1)
    else:  # ROS 1's default: publish once, latched, until Ctrl-C
        pub(graph, args.topic, args.type, values, rate=None, latch=True)


@program_main  # the console script's entry
def rostopic(argv: Sequence[str] | None = None) -> int:
    return tool.run(rostopic_parser(), argv)


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
            graph.wait_for(lambda: node_names_known(graph, topic), "")
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
        import yaml

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
    from rclpy.duration import Duration
    from rclpy.qos import DurabilityPolicy, QoSProfile

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


LATCH_MATCH_WAIT = 1.0  # s: how long a subscription seen in the graph is waited for to match


def _latch(graph: Graph, publisher: Publisher, msg: Any) -> None:
    """ROS 1 latching: every subscriber gets the message once. It is sent once, when the
    subscriptions running now have matched (with none yet, when the first one does, volatile
    or not), and the transient-local publisher keeps it for those that come later and ask for
    it: the tools' subscriptions do (ros2cmd/qos.py), and take it once. A volatile subscriber
    that joins after it was sent does not get it (docs/dev/limits.md)."""
    graph.settle()
    deadline = time.monotonic() + LATCH_MATCH_WAIT
    while True:
        subscriptions = len(graph.node.get_subscriptions_info_by_topic(publisher.topic_name))
        if not subscriptions:
            deadline = time.monotonic() + LATCH_MATCH_WAIT
        elif publisher.get_subscription_count() >= subscriptions or time.monotonic() > deadline:
            break
        graph.spin_once(0.1)
    publish_one(graph, publisher, msg)
    while True:
        graph.spin_once(0.1)


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
        publish_one(graph, publisher, msg)
        if verbose:
            print(f"publishing #{count}: {msg}", flush=True)
        next_time += 1.0 / rate


class _HzMeter(HzMeter):
    """ROS 1 rostopic hz's print rule on ros2topic's arithmetic."""

    def report(self) -> str | None:
        """Asked once a second: nothing before the second message, then the statistics, or
        `no new messages` when none came since the last report."""
        if not self.intervals:
            return None
        if self.last == self.last_printed:
            return "no new messages"
        self.last_printed = self.last
        return self.statistics(len(self.intervals) + 1)  # rostopic counts the messages


class _SizeMeter:
    """Arrival times and sizes in a sliding window: what `rostopic bw` prints."""

    def __init__(self, window: int) -> None:
        self.times: deque[float] = deque(maxlen=window)
        self.sizes: deque[int] = deque(maxlen=window)

    def add(self, raw: bytes) -> None:
        self.times.append(time.monotonic())
        self.sizes.append(len(raw))

    def report(self) -> str | None:
        """The bytes of the window over the time from its first message until now, as ROS 1's
        rostopic bw: after the publisher stops, the figure falls."""
        if len(self.times) < 2:
            return None
        rate = sum(self.sizes) / (time.monotonic() - self.times[0] or 1.0)
        return (
            f"{rate:.2f} B/s from {len(self.sizes)} messages\n"
            f"\tMessage size mean: {statistics.fmean(self.sizes):.0f} B"
        )


def hz(graph: Graph, topic: str, window: int = WINDOW, bandwidth: bool = False) -> None:
    """`rostopic hz` (or `bw`): the publishing rate (or bandwidth) of a topic, each second,
    until Ctrl-C."""
    with until_stopped():
        topic = absolute_name(topic)
        msg_type = _message_type(graph, topic, None)
        meter: _HzMeter | _SizeMeter = _SizeMeter(window) if bandwidth else _HzMeter(window - 1)
        # raw=True: count serialized messages without the cost of deserializing them.
        subscription = AdaptiveSubscription(graph, msg_type, topic, meter.add, raw=True)
        print(f"subscribed to [{topic}]", flush=True)
        next_report = time.monotonic() + 1.0
        while True:
            graph.spin_once(min(0.1, max(0.0, next_report - time.monotonic())))
            subscription.update()
            if time.monotonic() < next_report:
                continue
            next_report = time.monotonic() + 1.0  # rostopic sleeps a second between reports
            report = meter.report()
            if report:
                print(report, flush=True)
