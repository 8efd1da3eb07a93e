"""`ros2 topic ...`: list, echo, pub, hz, bw, delay, info, type and find, as ros2topic (ROS 2
Jazzy) has them: its options, and its output line for line (register() and the ros2_* functions
at the end). The functions before them serve ROS 1's `rostopic` (ros1/rostopic.py), whose
output stays ROS 1's where it differs (`rostopic hz`, `rostopic info`, latching `rostopic pub`).
"""

from __future__ import annotations

import argparse
import contextlib
import math
import statistics
import sys
import time
from collections import deque
from collections.abc import Callable
from typing import Any

import yaml
from rclpy.duration import Duration
from rclpy.event_handler import SubscriptionEventCallbacks
from rclpy.executors import ExternalShutdownException
from rclpy.publisher import Publisher
from rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from rclpy.time import Time

from ros2cmd.errors import ToolError
from ros2cmd.graph import (
    DEFAULT_TIMEOUT,
    MAX_SETTLE_TIME,
    Graph,
    absolute_name,
    is_hidden,
    print_names,
    until_stopped,
)
from ros2cmd.messages import (
    fill_message,
    message_to_csv,
    message_to_data,
    message_to_yaml,
    parse_yaml,
)
from ros2cmd.qos import AdaptiveSubscription, add_qos_arguments, qos_from_args, qos_overridden
from ros2cmd.qos import compatible_qos as compatible_qos  # moved to qos.py; kept importable
from ros2cmd.typenames import full_type_name, load_type
from ros2cmd.wait import spin_until
from ros_tutorials_common.bounded import InputError, read_text
from ros_tutorials_common.cli import positive_int, positive_rate, positive_seconds
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


# A volatile subscription gets the latched message sent again once it has lasted this long
# (s): the tools' own subscriptions start volatile and become transient-local within
# ros2cmd/qos.py's CHECK_PERIOD once they see the publisher, and those need no second copy.
VOLATILE_SETTLE = 0.6
LATCH_MATCH_WAIT = 1.0  # s: then how long its match is waited for


def _latch(graph: Graph, publisher: Publisher, msg: Any) -> None:
    """ROS 1 latching: every subscriber gets the message once, however late it joins. A
    transient-local subscription gets it from the publisher's history; a volatile one would
    miss it, so it is sent again for a volatile one that has joined and matched; only then,
    as every other subscriber gets that copy too (`rostopic hz` would count it)."""
    _publish_one(graph, publisher, msg)
    first_seen: dict[bytes, float] = {}  # volatile subscriptions: when seen first
    served: set[bytes] = set()  # those it was sent again for
    while True:
        now = time.monotonic()
        subscriptions = graph.node.get_subscriptions_info_by_topic(publisher.topic_name)
        volatile = {
            bytes(s.endpoint_gid)
            for s in subscriptions
            if s.qos_profile.durability == DurabilityPolicy.VOLATILE
        }
        first_seen = {gid: first_seen.get(gid, now) for gid in volatile}
        served &= volatile  # forget those that left
        due = {gid for gid, seen in first_seen.items() if now - seen >= VOLATILE_SETTLE}
        if due - served:
            matched = publisher.get_subscription_count() >= len(subscriptions)
            oldest = min(first_seen[gid] for gid in due - served)
            if matched or now - oldest > VOLATILE_SETTLE + LATCH_MATCH_WAIT:
                _publish_one(graph, publisher, msg)
                served |= due
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


class _SizeMeter:
    """Arrival times and sizes in a sliding window: what `rostopic bw` prints."""

    def __init__(self, window: int) -> None:
        self.times: deque[float] = deque(maxlen=window)
        self.sizes: deque[int] = deque(maxlen=window)

    def add(self, raw: bytes) -> None:
        self.times.append(time.monotonic())
        self.sizes.append(len(raw))


def hz(graph: Graph, topic: str, window: int = 10000, bandwidth: bool = False) -> None:
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
            report = meter.report_ros1() if isinstance(meter, _HzMeter) else _size_report(meter)
            if report:
                print(report, flush=True)


def _size_report(meter: _SizeMeter) -> str | None:
    if len(meter.times) < 2:
        return None
    rate = sum(meter.sizes) / (meter.times[-1] - meter.times[0] or 1.0)
    return (
        f"{rate:.2f} B/s from {len(meter.sizes)} messages\n"
        f"\tMessage size mean: {statistics.fmean(meter.sizes):.0f} B"
    )


# `ros2 topic`: ros2topic's sub-verbs, options and output (ROS 2 Jazzy).

TOPIC_HELP = "Various topic related sub-commands"
# Each sub-verb and the first line of its help, as `ros2 topic -h` lists them.
SUB_VERBS = {
    "bw": "Display bandwidth used by topic",
    "delay": "Display delay of topic from timestamp in header",
    "echo": "Output messages from a topic",
    "find": "Output a list of available topics of a given type",
    "hz": "Print the average publishing rate to screen",
    "info": "Print information about a topic",
    "list": "Output a list of available topics",
    "pub": "Publish a message to a topic",
    "type": "Print a topic's type",
}
HZ_WINDOW = 10000  # messages, as ros2topic hz and delay
BW_WINDOW = 100  # messages, as ros2topic bw
ECHO_TRUNCATE_LENGTH = 128  # strings and arrays longer than this end in '...'
WAIT_PERIOD = 0.1  # s between looks for matching subscriptions (pub -w)


def names_and_types(graph: Graph, hidden: bool = False) -> dict[str, list[str]]:
    """Every topic and its types; names with a part starting with '_' only if hidden."""
    return {
        name: types
        for name, types in graph.node.get_topic_names_and_types()
        if hidden or not is_hidden(name)
    }


def ros2_list(graph: Graph, args: argparse.Namespace) -> None:
    """`ros2 topic list [-t] [-c] [-v] [--include-hidden-topics]`."""
    graph.settle()
    topics = sorted(names_and_types(graph, args.include_hidden_topics).items())
    if args.count_topics:
        print(len(topics))
        return
    if args.verbose:
        for title, count, noun in (
            ("Published", graph.node.count_publishers, "publisher"),
            ("Subscribed", graph.node.count_subscribers, "subscriber"),
        ):
            print(f"{title} topics:")
            for name, types in topics:
                n = count(name)
                if n:
                    print(f" * {name} [{', '.join(types)}] {n} {noun}{'s' if n > 1 else ''}")
            print()
        return
    for name, types in topics:
        print(f"{name} [{', '.join(types)}]" if args.show_types else name)


def ros2_find(graph: Graph, args: argparse.Namespace) -> None:
    """`ros2 topic find TYPE [-c]`: the topics that carry the type."""
    wanted = full_type_name(load_type(args.topic_type, ("msg",)))  # unknown: an error first
    graph.settle()
    found = [
        name
        for name, types in sorted(names_and_types(graph, args.include_hidden_topics).items())
        if wanted in types
    ]
    if args.count_topics:
        print(len(found))
    for name in [] if args.count_topics else found:
        print(name)


def _wait_for_types(graph: Graph, topic: str) -> list[str]:
    """The topic's types, once it is in the graph (hidden ones too); ToolError after --timeout."""
    return graph.wait_for(
        lambda: names_and_types(graph, hidden=True).get(topic),
        f"unknown topic '{topic}': no publisher or subscriber seen",
    )


def ros2_type(graph: Graph, args: argparse.Namespace) -> None:
    for type_name in _wait_for_types(graph, absolute_name(args.topic_name)):
        print(type_name)


def ros2_info(graph: Graph, args: argparse.Namespace) -> None:
    """`ros2 topic info [-v] TOPIC`: the type and the counts; -v each endpoint as rclpy
    prints it (node, type, type hash, GID, QoS), every line followed by a blank one."""
    topic = absolute_name(args.topic_name)
    _wait_for_types(graph, topic)
    graph.settle()  # every endpoint that was there when the command started is counted
    if args.verbose:
        # Endpoints are discovered before the names of their nodes: wait for those too.
        with contextlib.suppress(ToolError):  # after --timeout, print what is known
            graph.wait_for(lambda: _node_names_known(graph, topic), "")
    types = names_and_types(graph, hidden=True)[topic]
    end = "\n\n" if args.verbose else "\n"
    print(f"Type: {types[0] if len(types) == 1 else types}", end=end)
    for title, endpoints in (
        ("Publisher", graph.node.get_publishers_info_by_topic(topic)),
        ("Subscription", graph.node.get_subscriptions_info_by_topic(topic)),
    ):
        print(f"{title} count: {len(endpoints)}", end=end)
        if args.verbose:
            for endpoint in endpoints:
                print(endpoint, end=end)


def _single_type(graph: Graph, topic: str, type_name: str | None) -> type:
    """The message class to subscribe with: the one given, else the topic's only type."""
    if type_name is not None:
        return load_type(type_name, ("msg",))
    types = _wait_for_types(graph, topic)
    if len(types) > 1:
        raise ToolError(
            f"Cannot echo topic '{topic}', as it contains more than one type: [{', '.join(types)}]"
        )
    return load_type(types[0], ("msg",))


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
        self.filter = _filter_expression(args.filter_expr)

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


def _filter_expression(expression: str | None) -> Callable[[Any], bool] | None:
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


def ros2_echo(graph: Graph, args: argparse.Namespace) -> None:
    """`ros2 topic echo TOPIC [TYPE]`: each message as YAML and '---', until Ctrl-C;
    --once the first one, --timeout N at most N seconds in all."""
    with until_stopped() if not args.once else contextlib.nullcontext():
        _ros2_echo(graph, args)


def _ros2_echo(graph: Graph, args: argparse.Namespace) -> None:
    deadline = time.monotonic() + args.timeout if args.timeout_given else math.inf
    topic = absolute_name(args.topic_name)
    msg_type = _single_type(graph, topic, args.message_type)
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
    other_type = _OtherType(graph, topic, msg_type)
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


class _OtherType:
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


def _lost_messages(status: Any) -> None:
    print(
        "A message was lost!!!\n\ttotal count change:"
        f"{status.total_count_change}\n\ttotal count: {status.total_count}",
        end="---\n",
        flush=True,
    )


def ros2_pub(graph: Graph, args: argparse.Namespace) -> None:
    """`ros2 topic pub TOPIC TYPE VALUES`: at --rate Hz until Ctrl-C, or --times / --once.

    Waits for -w matching subscriptions first (1 with --once or --times), saying so every
    second, as ros2topic does; with --max-wait-time-secs at most that long.
    """
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
        other_type = _OtherType(graph, topic, msg_type)
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
            _publish_one(graph, publisher, msg)
            next_time += 1.0 / args.rate
        # Time for the last message to reach the wire (and reliable subscribers) before exit.
        publisher.wait_for_all_acked(Duration(seconds=graph.timeout))
        spin_until(graph.executor, lambda: False, args.keep_alive)


def _wait_for_subscriptions(
    graph: Graph,
    publisher: Publisher,
    wanted: int,
    max_wait: float | None,
    other_type: _OtherType | None = None,
) -> None:
    waited = 0.0
    since_said = 0
    while publisher.get_subscription_count() < wanted:
        if other_type is not None:
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


def _subscribe_when_known(graph: Graph, topic: str, callback: Callable, raw: bool) -> type:
    """hz, bw and delay: once the topic is in the graph, subscribe as ros2topic does
    (sensor-data QoS, which hears reliable and best-effort publishers alike)."""
    topic = absolute_name(topic)
    try:
        types = _wait_for_types(graph, topic)
    except ToolError:
        print(f"WARNING: topic [{topic}] does not appear to be published yet", flush=True)
        types = graph.wait_for(
            lambda: names_and_types(graph, hidden=True).get(topic), "", timeout=math.inf
        )
    if len(types) > 1:
        raise ToolError(
            f"Cannot echo topic '{topic}', as it contains more than one type: [{', '.join(types)}]"
        )
    msg_type = load_type(types[0], ("msg",))
    graph.node.create_subscription(msg_type, topic, callback, qos_profile_sensor_data, raw=raw)
    return msg_type


def ros2_hz(graph: Graph, args: argparse.Namespace) -> None:
    """`ros2 topic hz TOPIC`: the rate over the last --window messages, about once a second
    (once a second of messages has arrived since the last report)."""
    with until_stopped():
        meter = _HzMeter(args.window_size)
        _subscribe_when_known(graph, args.topic_name, meter.add, raw=args.filter_expr is None)
        meter.keep = _filter_expression(args.filter_expr)
        while True:
            graph.spin_once(0.1)
            report = meter.report()
            if report:
                print(report, flush=True)


class _HzMeter:
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
        return self._statistics(len(self.intervals))

    def report_ros1(self) -> str | None:
        """ROS 1 rostopic hz's rule, asked once a second: nothing before the second message,
        then the statistics, or `no new messages` when none came since the last report."""
        if not self.intervals:
            return None
        if self.last == self.last_printed:
            return "no new messages"
        self.last_printed = self.last
        return self._statistics(len(self.intervals) + 1)  # rostopic counts the messages

    def _statistics(self, window: int) -> str:
        n = len(self.intervals)
        mean = sum(self.intervals) / n
        rate = 1.0 / mean if mean > 0 else 0.0
        std_dev = math.sqrt(sum((x - mean) ** 2 for x in self.intervals) / n)
        return (
            f"average rate: {rate * 1e9:.3f}\n\tmin: {min(self.intervals) * 1e-9:.3f}s "
            f"max: {max(self.intervals) * 1e-9:.3f}s std dev: {std_dev * 1e-9:.5f}s "
            f"window: {window}"
        )


def ros2_bw(graph: Graph, args: argparse.Namespace) -> None:
    """`ros2 topic bw TOPIC`: bytes per second over the last --window messages, each second."""
    with until_stopped():
        arrivals: deque[tuple[int, int]] = deque(maxlen=args.window)  # (time ns, bytes)
        topic = absolute_name(args.topic)
        _subscribe_when_known(
            graph, topic, lambda raw: arrivals.append((time.time_ns(), len(raw))), raw=True
        )
        print(f"Subscribed to [{topic}]", flush=True)
        next_report = time.monotonic() + 1.0
        while True:
            graph.spin_once(min(0.1, max(0.0, next_report - time.monotonic())))
            if time.monotonic() < next_report:
                continue
            next_report += 1.0
            if len(arrivals) >= 2:
                print(_bandwidth(list(arrivals), time.time_ns()), flush=True)


def _bandwidth(arrivals: list[tuple[int, int]], now: int) -> str:
    sizes = [size for _, size in arrivals]
    total = sum(sizes)
    per_second = total / ((now - arrivals[0][0]) * 1e-9)
    figures = (per_second, total / len(sizes), min(sizes), max(sizes))
    if per_second < 1000:
        rate, mean, low, high = (f"{x:.0f} B" for x in figures)
    elif per_second < 1_000_000:
        rate, mean, low, high = (f"{x / 1000:.2f} KB" for x in figures)
    else:
        rate, mean, low, high = (f"{x / 1000 / 1000:.2f} MB" for x in figures)
    return (
        f"{rate}/s from {len(sizes)} messages\n\tMessage size mean: {mean} min: {low} max: {high}"
    )


def ros2_delay(graph: Graph, args: argparse.Namespace) -> None:
    """`ros2 topic delay TOPIC`: how old header.stamp is when each message arrives, each second."""
    with until_stopped():
        delays: deque[int] = deque(maxlen=args.window)  # ns
        new = [False]

        def on_message(msg: Any) -> None:
            now = graph.node.get_clock().now()
            delays.append((now - Time.from_msg(msg.header.stamp)).nanoseconds)
            new[0] = True

        topic = absolute_name(args.topic)
        msg_type = _single_type(graph, topic, None)
        if "header" not in msg_type.get_fields_and_field_types():
            raise ToolError(f"msg does not have header: {full_type_name(msg_type)} has none")
        _subscribe_when_known(graph, topic, on_message, raw=False)
        next_report = time.monotonic() + 1.0
        while True:
            graph.spin_once(min(0.1, max(0.0, next_report - time.monotonic())))
            if time.monotonic() < next_report:
                continue
            next_report += 1.0
            if not delays:
                continue
            if not new[0]:
                print("no new messages", flush=True)
                continue
            new[0] = False
            n = len(delays)
            mean = sum(delays) / n
            std_dev = math.sqrt(sum((x - mean) ** 2 for x in delays) / n)
            print(
                f"average delay: {mean * 1e-9:.3f}\n\tmin: {min(delays) * 1e-9:.3f}s "
                f"max: {max(delays) * 1e-9:.3f}s std dev: {std_dev * 1e-9:.5f}s window: {n}",
                flush=True,
            )


class _GivenAction(argparse.Action):
    """Stores the value and notes that the option was given (echo's --timeout)."""

    def __call__(self, parser, namespace, values, option_string=None) -> None:
        setattr(namespace, self.dest, values)
        setattr(namespace, f"{self.dest}_given", True)


def nonnegative_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer of 0 or more")
    return value


def _graph_options(parser: argparse.ArgumentParser, timeout_help: str | None = None) -> None:
    """--spin-time and --timeout (this project's waits), --no-daemon (see daemon.py)."""
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


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    """`ros2 topic` and its sub-verbs, as ros2topic has them."""
    parser = verbs.add_parser(
        "topic",
        help=TOPIC_HELP,
        description=TOPIC_HELP,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "--include-hidden-topics", action="store_true", help="Consider hidden topics as well"
    )
    width = max(len(name) for name in SUB_VERBS)
    sub = parser.add_subparsers(
        dest="command",
        title="Commands",
        description="".join(f"{name.ljust(width)}  {text}\n" for name, text in SUB_VERBS.items()),
        metavar="Call `ros2 topic <command> -h` for more detailed usage.",
    )
    parser.set_defaults(offline=True, run=lambda _graph, _args: parser.print_help())

    def verb(name: str, run: Callable[[Graph, argparse.Namespace], None]) -> Any:
        p = sub.add_parser(
            name,
            description=SUB_VERBS[name],
            formatter_class=argparse.RawDescriptionHelpFormatter,
        )
        p.set_defaults(run=run, offline=False)
        return p

    def hidden_option(p: argparse.ArgumentParser) -> None:
        # Also after the sub-verb; SUPPRESS keeps `ros2 topic --include-hidden-topics list`.
        p.add_argument(
            "--include-hidden-topics",
            action="store_true",
            default=argparse.SUPPRESS,
            help="Consider hidden topics as well",
        )

    p = verb("bw", ros2_bw)
    p.add_argument("topic", help="Topic name to monitor for bandwidth utilization")
    p.add_argument(
        "--window",
        "-w",
        type=positive_int,
        default=BW_WINDOW,
        metavar="WINDOW",
        help=f"maximum window size, in # of messages, for calculating rate (default: {BW_WINDOW})",
    )
    _graph_options(p)

    p = verb("delay", ros2_delay)
    p.add_argument("topic", help="Topic name to calculate the delay for")
    p.add_argument(
        "--window",
        "-w",
        type=positive_int,
        default=HZ_WINDOW,
        help=f"window size, in # of messages, for calculating rate (default: {HZ_WINDOW})",
    )
    _graph_options(p)

    p = verb("echo", ros2_echo)
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
        default=ECHO_TRUNCATE_LENGTH,
        help="The length to truncate arrays, bytes, and string to "
        f"(default: {ECHO_TRUNCATE_LENGTH})",
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
    hidden_option(p)
    _graph_options(
        p,
        "Set a timeout in seconds for waiting: for the topic to appear (default "
        f"{DEFAULT_TIMEOUT:g}) and, when given, for messages (then exit)",
    )

    p = verb("find", ros2_find)
    p.set_defaults(daemon=True)
    p.add_argument(
        "topic_type", help="Name of the ROS topic type to filter for (e.g. 'std_msg/msg/String')"
    )
    p.add_argument(
        "-c",
        "--count-topics",
        action="store_true",
        help="Only display the number of topics discovered",
    )
    hidden_option(p)
    _graph_options(p)

    p = verb("hz", ros2_hz)
    p.add_argument("topic_name", help="Name of the ROS topic to listen to (e.g. '/chatter')")
    p.add_argument(
        "--window",
        "-w",
        dest="window_size",
        type=positive_int,
        default=HZ_WINDOW,
        metavar="WINDOW",
        help=f"window size, in # of messages, for calculating rate (default: {HZ_WINDOW})",
    )
    p.add_argument(
        "--filter",
        dest="filter_expr",
        metavar="EXPR",
        help="only measure messages matching the specified Python expression",
    )
    _graph_options(p)

    p = verb("info", ros2_info)
    p.add_argument("topic_name", help="Name of the ROS topic to get info (e.g. '/chatter')")
    p.add_argument(
        "--verbose",
        "-v",
        action="store_true",
        help="Prints detailed information like the node name, node namespace, topic type, "
        "topic type hash, GUID, and QoS Profile of the publishers and subscribers to this topic",
    )
    _graph_options(p)

    p = verb("list", ros2_list)
    p.set_defaults(daemon=lambda a: not a.verbose)  # -v counts endpoints: a node of its own
    p.add_argument(
        "-t", "--show-types", action="store_true", help="Additionally show the topic type"
    )
    p.add_argument(
        "-c",
        "--count-topics",
        action="store_true",
        help="Only display the number of topics discovered",
    )
    hidden_option(p)
    p.add_argument(
        "-v", "--verbose", action="store_true", help="List full details about each topic"
    )
    _graph_options(p)

    p = verb("pub", ros2_pub)
    p.add_argument("topic_name", help="Name of the ROS topic to publish to (e.g. '/chatter')")
    p.add_argument("message_type", help="Type of the ROS message (e.g. 'std_msgs/String')")
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
    _graph_options(p)

    p = verb("type", ros2_type)
    p.add_argument("topic_name", help="Name of the ROS topic to get type (e.g. '/chatter')")
    _graph_options(p)
