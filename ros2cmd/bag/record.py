"""`ros2 bag record` / `rosbag record`: write topics and services into a rosbag2 bag (MCAP).

Each topic gets a raw subscription (``raw=True``): the serialized CDR bytes are written as
they arrive, with the receive time as the MCAP log time and the publisher's send time as
its publish time, as rosbag2 does; nothing is deserialized. A topic is subscribed once it
has a publisher, with a QoS that matches the publishers (``compatible_qos``: a latching,
transient-local publisher's message is recorded too), and the publishers' offered QoS is
stored with the topic so that `play` can offer the same.

Which topics: rosbag2's TopicFilter (Jazzy), see ``TopicFilter``. A service is recorded
through its introspection topic ``/<service>/_service_event`` (type ``pkg/srv/Name_Event``),
which a node publishes once introspection is configured on its service or client.

`ros2 bag record` runs a node named ``rosbag2_recorder`` (``--node-name``) and logs through it
the lines rosbag2's recorder logs; `rosbag record` prints ROS 1-like lines and the bag's
info at the end. Ctrl-C and SIGTERM end the recording: the file gets its summary and
metadata.yaml its final counts. The signal handlers only set a flag, so a signal never lands
in the middle of a write.
"""

from __future__ import annotations

import re
import sys
import time
from dataclasses import dataclass, field
from typing import Any

import rclpy.logging
from rclpy.event_handler import SubscriptionEventCallbacks
from rclpy.node import Node
from rclpy.qos import HistoryPolicy, QoSProfile

from ros2cmd.bag.info import is_service_event_topic, ros1_info, service_name, service_type
from ros2cmd.bag.keyboard import Keyboard
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name, is_hidden
from ros2cmd.qos import compatible_qos
from ros2cmd.typenames import load_type
from ros_tutorials_common.ros import RCLError
from ros_tutorials_common.shutdown import StopSignals
from rosbag2.definitions import schema
from rosbag2.errors import BagError
from rosbag2.loss import LossCount
from rosbag2.metadata import TopicInfo
from rosbag2.offered_qos import qos_to_dict
from rosbag2.reader import BagReader
from rosbag2.writer import BagWriter, default_bag_name

SPIN_PERIOD = 0.05
FINAL_DRAIN_TIME = 5.0  # seconds at most to take what arrived before the stop
DRAIN_LIMIT = 1000  # messages taken per topic in one go, so that no topic starves the others
LOSS_REPORT_PERIOD = 1.0  # s between reports of messages lost before the recorder got them


@dataclass
class RecordOptions:
    """What to record and how (rosbag2_transport's RecordOptions, the parts used here)."""

    topics: list[str] = field(default_factory=list)
    services: list[str] = field(default_factory=list)  # their /_service_event topics
    all_topics: bool = False
    all_services: bool = False
    topic_types: list[str] = field(default_factory=list)
    regex: str = ""
    exclude_regex: str = ""
    exclude_topic_types: list[str] = field(default_factory=list)
    exclude_topics: list[str] = field(default_factory=list)
    exclude_services: list[str] = field(default_factory=list)  # /_service_event topics
    include_unpublished_topics: bool = False
    include_hidden_topics: bool = False
    ignore_leaf_topics: bool = False
    no_discovery: bool = False
    polling_interval: float = 0.1  # seconds
    start_paused: bool = False
    keyboard: bool = True
    node_name: str = "rosbag2_recorder"
    duration: float | None = None  # this project's: stop after this many seconds
    max_messages: int | None = None  # this project's: stop after this many messages
    custom_data: dict[str, str] | None = None  # stored in metadata.yaml's custom_data
    ros1: bool = False  # `rosbag record`: ROS 1's lines, no node of its own

    def __post_init__(self) -> None:
        self.topics = [absolute_name(t) for t in self.topics]
        self.services = [absolute_name(s) for s in self.services]
        self.exclude_topics = [absolute_name(t) for t in self.exclude_topics]
        self.exclude_services = [absolute_name(s) for s in self.exclude_services]


class TopicFilter:
    """rosbag2_transport's TopicFilter::take_topic (Jazzy), step for step."""

    def __init__(self, options: RecordOptions, graph: Graph, warn: Any) -> None:
        self.options = options
        self.graph = graph
        self.warn = warn  # warn(logger_name, text): rosbag2's warnings, each once
        self.regex = re.compile(options.regex) if options.regex else None
        self.exclude_regex = re.compile(options.exclude_regex) if options.exclude_regex else None

    def take(self, topic: str, types: list[str]) -> bool:
        o = self.options
        if len(set(types)) != 1:
            return False
        topic_type = types[0]
        if not is_service_event_topic(topic, topic_type):
            if not (o.all_topics or o.topics or o.topic_types or o.regex) and not (
                o.include_hidden_topics
            ):
                return False
            if (
                not o.all_topics
                and topic not in o.topics
                and topic_type not in o.topic_types
                and not (self.regex and self.regex.search(topic))
            ):
                return False
            if topic_type in o.exclude_topic_types or topic in o.exclude_topics:
                return False
            if self.exclude_regex and self.exclude_regex.search(topic):
                return False
            if not o.include_hidden_topics and is_hidden(topic):
                self.warn(
                    "rosbag2_transport",
                    "Hidden topics are not recorded. Enable them with --include-hidden-topics",
                )
                return False
        else:
            if not (o.all_services or o.services or o.regex):
                return False
            service = service_name(topic)
            if (
                not o.all_services
                and topic not in o.services
                and not (self.regex and self.regex.search(service))
            ):
                return False
            if topic in o.exclude_services:
                return False
            if self.exclude_regex and self.exclude_regex.search(service):
                return False
        node = self.graph.node
        if not o.include_unpublished_topics and not node.get_publishers_info_by_topic(topic):
            return False
        return not (o.ignore_leaf_topics and not node.get_subscriptions_info_by_topic(topic))


def message_class(type_name: str) -> type:
    """The Python class of a topic's type; a service event type is the service's ``Event``."""
    if type_name.endswith("_Event") and "/srv/" in type_name:
        return load_type(service_type(type_name), ("srv",)).Event  # type: ignore[attr-defined]
    return load_type(type_name, ("msg",))


def _type_hash(endpoints: list[Any]) -> str:
    """The topic's type hash if every publisher that offers one agrees (as rosbag2 does)."""
    hashes = {str(e.topic_type_hash) for e in endpoints if e.topic_type_hash.version > 0}
    return hashes.pop() if len(hashes) == 1 else ""


class Recorder:
    """Subscribe to the topics the filter takes and write what arrives."""

    def __init__(
        self, graph: Graph, writer: BagWriter, options: RecordOptions, node: Node | None = None
    ) -> None:
        self.graph = graph
        self.writer = writer
        self.options = options
        self.node = node or graph.node  # the node that subscribes (and logs, for ros2)
        self.filter = TopicFilter(options, graph, self.warn_once)
        self.subscriptions: dict[str, Any] = {}
        self.skipped: set[str] = set()
        self.warned: set[str] = set()
        self.stop_reason = ""
        self.paused = options.start_paused
        self.discovering = True
        self.limit_reached = False  # --max-messages: nothing more is written
        self.stop_ns = 0  # once stopping: messages received after this are not written
        self.loss = LossCount()

    # What the user sees

    def info(self, text: str) -> None:
        """One of rosbag2_recorder's log lines (ros2), or a printed line (rosbag)."""
        if self.options.ros1:
            print(text, flush=True)
        else:
            self.node.get_logger().info(text)

    def warn_once(self, logger: str, text: str) -> None:
        if text in self.warned:
            return
        self.warned.add(text)
        if self.options.ros1:
            print(f"warning: {text}", file=sys.stderr, flush=True)
        else:
            rclpy.logging.get_logger(logger).warning(text)

    # Discovery

    def discover(self) -> None:
        """Subscribe to every topic the filter takes that is not subscribed yet."""
        for topic, types in sorted(self.graph.node.get_topic_names_and_types()):
            if topic in self.subscriptions or topic in self.skipped:
                continue
            if self.filter.take(topic, types):
                self._subscribe(topic, types[0])

    def discovery_round(self) -> None:
        """rosbag2's discovery thread: look again, stop once every topic named is subscribed."""
        self.discover()
        wanted = self.options.topics
        if wanted and len(self.subscriptions) == len(wanted) and not self.options.ros1:
            self.info("All requested topics are subscribed. Stopping discovery...")
            self.discovering = False

    def _subscribe(self, topic: str, type_name: str) -> None:
        try:
            msg_type = message_class(type_name)
        except ToolError as error:
            self.skipped.add(topic)
            self.warn_once(
                "rosbag2_transport",
                f"Topic '{topic}' has unknown type '{type_name}' . Only topics with known type "
                f"are supported. Reason: '{error}'",
            )
            return
        try:
            definition, encoding = schema(type_name)
        except (ToolError, ValueError) as error:
            definition, encoding = "", "unknown"  # as rosbag2 leaves it then
            self.warn_once("rosbag2_cpp", f"{topic}: no definition stored ({error})")
        publishers = self.graph.node.get_publishers_info_by_topic(topic)
        info = TopicInfo(
            name=topic,
            type=type_name,
            offered_qos_profiles=[qos_to_dict(p.qos_profile) for p in publishers],
            type_description_hash=_type_hash(publishers),
        )
        self.writer.add_topic(info, definition, encoding)
        qos: QoSProfile = compatible_qos(self.graph, topic)
        # Keep all: a reliable publisher then waits for the recorder rather than the
        # recorder's queue dropping what it has not taken yet (a burst while writing a chunk).
        qos.history = HistoryPolicy.KEEP_ALL
        lost = SubscriptionEventCallbacks(
            message_lost=lambda event, name=topic: self.loss.middleware_lost(
                name, event.total_count
            )
        )
        self.subscriptions[topic] = self.node.create_subscription(
            msg_type,
            topic,
            lambda data, message_info, name=topic: self._received(name, data, message_info),
            qos,
            raw=True,
            event_callbacks=lost,
        )
        if self.options.ros1:
            self.info(f"Subscribed to topic '{topic}' ({type_name})")
        else:
            self.info(f"Subscribed to topic '{topic}'")

    # Messages

    def drain_all(self) -> bool:
        """One drain at the end; True while it still found messages (and may write more)."""
        before = self.writer.message_count
        self.drain()
        return self.writer.message_count > before and not self.limit_reached

    def drain(self) -> None:
        """Take what else is waiting, without a round through the executor for each message.

        The executor wakes up for the first message of a burst; taking the rest directly, a
        topic's batch at a time, costs a fraction of its per-callback overhead (which at 1 kHz
        is most of the recorder's CPU).
        """
        for topic, subscription in self.subscriptions.items():
            if self.limit_reached:
                return
            taken = []
            with subscription.handle:
                take = subscription.handle.take_message
                for _ in range(DRAIN_LIMIT):
                    message = take(subscription.msg_type, True)
                    if message is None:
                        break
                    taken.append(message)
            if taken:
                self._received_many(topic, taken)

    def _received(self, topic: str, data: bytes, message_info: dict[str, Any]) -> None:
        self._received_many(topic, [(data, message_info)])

    def _received_many(self, topic: str, taken: list[tuple[bytes, dict[str, Any]]]) -> None:
        """Messages of one topic as taken: (serialized bytes, message info)."""
        infos = [info for _, info in taken]
        self.loss.received_many(topic, [info.get("publication_sequence_number") for info in infos])
        if self.paused or self.limit_reached:
            return
        now = time.time_ns()
        batch = [
            (data, info.get("received_timestamp") or now, info.get("source_timestamp") or 0)
            for data, info in taken
        ]
        if self.stop_ns:  # stopping: what arrived after the stop is not written
            batch = [message for message in batch if message[1] <= self.stop_ns]
        limit = self.options.max_messages
        if limit is not None:
            batch = batch[: max(0, limit - self.writer.message_count)]
        self.writer.write_many(topic, batch)
        if limit is not None and self.writer.message_count >= limit:
            self.limit_reached = True
            self.stop_reason = f"{limit} messages recorded"

    def report_loss(self) -> None:
        """Say what was lost since the last report, per topic (loss.py)."""
        self.loss.look_at_publishers(self.graph.node.count_publishers)
        for topic, new, total in self.loss.news():
            self.warn(
                f"{new} messages on {topic} were lost before the recorder received them "
                f"({total} in all)"
            )

    def warn(self, text: str) -> None:
        if self.options.ros1:
            print(f"warning: {text}", file=sys.stderr, flush=True)
        else:
            self.node.get_logger().warning(text)

    def toggle_paused(self) -> None:
        self.paused = not self.paused
        self.info("Pausing recording." if self.paused else "Resuming recording.")


def _check_names(graph: Graph, names: list[str]) -> None:
    """A name rcl refuses ('bad topic') can never appear: refuse it now instead of waiting."""
    for name in names:
        try:
            graph.node.resolve_topic_name(name)
        except RCLError as error:
            reason = str(error).split(", at ")[0].removeprefix("failed to resolve name: ")
            raise ToolError(f"invalid topic name '{name}': {reason}") from None


def record(graph: Graph, options: RecordOptions, output: str | None) -> None:
    _check_names(graph, [*options.topics, *options.services, *options.exclude_topics])
    stop = StopSignals()  # the loop looks between callbacks
    writer = BagWriter(output or default_bag_name(), custom_data=options.custom_data)
    node = None
    if not options.ros1:
        # rosbag2's recorder is a node of the graph, named rosbag2_recorder.
        node = Node(options.node_name, context=graph.node.context)
        graph.executor.add_node(node)
    recorder = Recorder(graph, writer, options, node)
    keyboard = Keyboard(enabled=options.keyboard)
    error: ToolError | None = None
    try:
        _run(graph, recorder, writer, options, stop, keyboard)
    except BagError as failure:
        error = failure
    finally:
        keyboard.restore()
        recorder.report_loss()
        if recorder.loss.totals():
            writer.custom_data = {**(writer.custom_data or {}), **recorder.loss.custom_data()}
        for subscription in recorder.subscriptions.values():
            recorder.node.destroy_subscription(subscription)
        if not options.ros1:
            # rosbag2's cache consumer says so when the writer closes.
            rclpy.logging.get_logger("rosbag2_cpp").info(
                "Writing remaining messages from cache to the bag. It may take a while"
            )
        try:
            writer.close()
        except BagError as failure:
            error = error or failure
        if node is not None:
            recorder.info("Recording stopped")
            graph.executor.remove_node(node)
            node.destroy_node()
    if error is not None:
        raise error
    if options.ros1:
        reason = recorder.stop_reason or f"{stop.name} received"
        print(f"Recording stopped ({reason}): {writer.message_count} messages", flush=True)
        with BagReader(writer.folder) as reader:
            print(ros1_info(reader.bag), flush=True)


def _run(
    graph: Graph,
    recorder: Recorder,
    writer: BagWriter,
    options: RecordOptions,
    stop: StopSignals,
    keyboard: Keyboard,
) -> None:
    if options.ros1:
        print(f"Recording to '{writer.folder}' (rosbag2, mcap storage)", flush=True)
        if options.topics:
            print("Waiting for: " + ", ".join(options.topics), flush=True)
    else:
        if options.keyboard:
            recorder.info("Press SPACE for pausing/resuming")
        # (rosbag2 logs "Event publisher thread: Starting" here: its thread publishes bag split
        # events. This recorder neither splits bags nor has that thread, so it says nothing.)
        recorder.info("Listening for topics...")
        # What runs already is subscribed before "Recording...", as the page shows it: the
        # graph first holds every participant running now (rosbag2 looks at once, and a
        # topic its node has not discovered yet comes after that line).
        graph.settle()
    recorder.discover()
    if not options.ros1:
        if options.start_paused:
            recorder.info("Wait for recording: Press SPACE to start.")
        else:
            recorder.info("Recording...")
    recorder.discovering = not options.no_discovery
    start = time.monotonic()
    last_discovery = 0.0  # the discovery thread's first round comes at once
    last_loss_report = start
    while not (stop.name or recorder.stop_reason):
        now = time.monotonic()
        if options.duration is not None and now - start >= options.duration:
            recorder.stop_reason = f"--duration {options.duration:g} s reached"
            break
        if recorder.discovering and now - last_discovery >= options.polling_interval:
            last_discovery = now
            recorder.discovery_round()
        graph.spin_once(SPIN_PERIOD)
        recorder.drain()
        if keyboard.active and keyboard.wait(0) == "SPACE":
            recorder.toggle_paused()
        writer.flush_if_due()  # quiet topics too: nothing older than a period is at risk
        if now - last_loss_report >= LOSS_REPORT_PERIOD:
            last_loss_report = now
            recorder.report_loss()
    # What arrived before the stop is recorded too, however late this process got to it.
    recorder.stop_ns = time.time_ns()
    deadline = time.monotonic() + FINAL_DRAIN_TIME
    while recorder.drain_all() and time.monotonic() < deadline:
        pass
    if not options.ros1 and not recorder.paused:
        recorder.paused = True
        recorder.info("Pausing recording.")
