"""`rosbag record` / `ros2 bag record`: write topics into a rosbag2 bag (MCAP storage).

Each topic gets a raw subscription (``raw=True``): the serialized CDR bytes are written as
they arrive, with the receive time as the MCAP log time and the publisher's send time as
its publish time, as rosbag2 does; nothing is deserialized. A topic is subscribed once it
has a publisher, with a QoS that matches the publishers (``compatible_qos``: a latching,
transient-local publisher's message is recorded too), and the publishers' offered QoS is
stored with the topic so that `play` can offer the same. `-a` keeps looking for topics
that appear later.

Ctrl-C and SIGTERM end the recording: the file gets its summary and metadata.yaml its
final counts, then the bag's info is printed. The signal handlers only set a flag, so a
signal never lands in the middle of a write.
"""

from __future__ import annotations

import signal
import sys
import time
from typing import Any

from rclpy.qos import HistoryPolicy, QoSProfile

from ros2cmd.bag import definitions
from ros2cmd.bag.info import ros1_info, ros2_info
from ros2cmd.bag.storage import (
    BagError,
    BagReader,
    BagWriter,
    TopicInfo,
    default_bag_name,
    qos_to_dict,
)
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name, is_hidden
from ros2cmd.topic import compatible_qos
from ros2cmd.typenames import load_type

DISCOVERY_PERIOD = 0.1  # seconds between looks at the graph for new topics
SPIN_PERIOD = 0.05
FINAL_DRAIN_TIME = 5.0  # seconds at most to take what arrived before the stop
DRAIN_LIMIT = 1000  # messages taken per topic in one go, so that no topic starves the others


def _type_hash(endpoints: list[Any]) -> str:
    """The topic's type hash if every publisher that offers one agrees (as rosbag2 does)."""
    hashes = {str(e.topic_type_hash) for e in endpoints if e.topic_type_hash.version > 0}
    return hashes.pop() if len(hashes) == 1 else ""


class Recorder:
    """Subscribe to the topics (all with topics=None) and write what arrives."""

    def __init__(
        self,
        graph: Graph,
        writer: BagWriter,
        topics: list[str] | None,
        max_messages: int | None = None,
    ) -> None:
        self.graph = graph
        self.writer = writer
        self.wanted = None if topics is None else [absolute_name(t) for t in topics]
        self.max_messages = max_messages
        self.subscriptions: dict[str, Any] = {}
        self.skipped: set[str] = set()
        self.stop_reason = ""
        self.limit_reached = False  # --max-messages: nothing more is written
        self.stop_ns = 0  # once stopping: messages received after this are not written

    def discover(self) -> None:
        """Subscribe to every wanted topic that has a publisher and is not subscribed yet."""
        for topic, types in sorted(self.graph.node.get_topic_names_and_types()):
            if topic in self.subscriptions or topic in self.skipped:
                continue
            if self.wanted is None and is_hidden(topic):
                continue
            if self.wanted is not None and topic not in self.wanted:
                continue
            publishers = self.graph.node.get_publishers_info_by_topic(topic)
            if not publishers:
                continue
            self._subscribe(topic, types[0], publishers)

    def _subscribe(self, topic: str, type_name: str, publishers: list[Any]) -> None:
        try:
            msg_type = load_type(type_name, ("msg",))
        except ToolError as error:
            self.skipped.add(topic)
            print(f"warning: not recording {topic}: {error}", file=sys.stderr, flush=True)
            return
        try:
            definition = definitions.message_definition(type_name)
            encoding = definitions.SCHEMA_ENCODING
        except ToolError as error:
            definition, encoding = "", "unknown"  # as rosbag2 leaves it then
            print(f"warning: {topic}: no definition stored ({error})", file=sys.stderr)
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
        self.subscriptions[topic] = self.graph.node.create_subscription(
            msg_type,
            topic,
            lambda data, message_info, name=topic: self._received(name, data, message_info),
            qos,
            raw=True,
        )
        print(f"Subscribed to topic '{topic}' ({type_name})", flush=True)

    def drain_all(self) -> bool:
        """One drain at the end; True while it still found messages (and may write more)."""
        before = self.writer.message_count
        self.drain()
        return self.writer.message_count > before and not self.limit_reached

    def drain(self) -> None:
        """Take what else is waiting, without a round through the executor for each message.

        The executor wakes up for the first message of a burst; taking the rest directly costs
        a fraction of its per-callback overhead (which at 1 kHz is most of the recorder's CPU).
        """
        for topic, subscription in self.subscriptions.items():
            for _ in range(DRAIN_LIMIT):
                if self.limit_reached:
                    return
                with subscription.handle:
                    taken = subscription.handle.take_message(subscription.msg_type, True)
                if taken is None:
                    break
                self._received(topic, taken[0], taken[1])

    def _received(self, topic: str, data: bytes, message_info: dict[str, Any]) -> None:
        received = message_info.get("received_timestamp") or time.time_ns()
        if self.limit_reached or (self.stop_ns and received > self.stop_ns):
            return
        self.writer.write(topic, data, received, message_info.get("source_timestamp") or 0)
        if self.max_messages is not None and self.writer.message_count >= self.max_messages:
            self.limit_reached = True
            self.stop_reason = f"{self.max_messages} messages recorded"


class _StopFlag:
    """Ctrl-C and SIGTERM set it; the loop looks at it between callbacks."""

    def __init__(self) -> None:
        self.signal_name = ""
        for number in (signal.SIGINT, signal.SIGTERM):
            signal.signal(number, self._handle)

    def _handle(self, number: int, _frame: Any) -> None:
        self.signal_name = signal.Signals(number).name


def record(
    graph: Graph,
    topics: list[str],
    all_topics: bool,
    output: str | None,
    duration: float | None,
    max_messages: int | None,
    ros1: bool = False,
) -> None:
    if not topics and not all_topics:
        raise ToolError("name the topics to record, or give -a for all of them")
    stop = _StopFlag()
    writer = BagWriter(output or default_bag_name())
    recorder = Recorder(graph, writer, None if all_topics else topics, max_messages)
    print(f"Recording to '{writer.folder}' (rosbag2, mcap storage)", flush=True)
    if recorder.wanted:
        print("Waiting for: " + ", ".join(recorder.wanted), flush=True)
    start = time.monotonic()
    last_discovery = 0.0
    error: ToolError | None = None
    try:
        while not (stop.signal_name or recorder.stop_reason):
            now = time.monotonic()
            if duration is not None and now - start >= duration:
                recorder.stop_reason = f"--duration {duration:g} s reached"
                break
            if now - last_discovery >= DISCOVERY_PERIOD:
                last_discovery = now
                recorder.discover()
            graph.spin_once(SPIN_PERIOD)
            recorder.drain()
            writer.flush_if_due()  # quiet topics too: nothing older than a period is at risk
        # What arrived before the stop is recorded too, however late this process got to it.
        recorder.stop_ns = time.time_ns()
        deadline = time.monotonic() + FINAL_DRAIN_TIME
        while recorder.drain_all() and time.monotonic() < deadline:
            pass
    except BagError as failure:
        error = failure
    finally:
        for subscription in recorder.subscriptions.values():
            graph.node.destroy_subscription(subscription)
        try:
            writer.close()
        except BagError as failure:
            error = error or failure
    if error is not None:
        raise error
    reason = recorder.stop_reason or f"{stop.signal_name} received"
    print(f"Recording stopped ({reason}): {writer.message_count} messages", flush=True)
    with BagReader(writer.folder) as reader:
        print(ros1_info(reader.bag) if ros1 else ros2_info(reader.bag), flush=True)
