"""`ros2 bag play BAG` / `rosbag play BAG`: publish a bag's messages as they were recorded.

Each message goes out as the bytes that were recorded (``publish`` of ``bytes`` is rclpy's
raw publish), at its recorded time relative to the first one, scaled by ``--rate``. Each
topic's publisher offers the reliability and durability its recorded publishers offered
(rosbag2 stores them as ``offered_qos_profiles``), so a latched topic is latched again.
A topic whose type is not installed here is skipped with a warning; the rest plays.

A service's recorded events (``/<service>/_service_event``) are published as that topic, or,
with ``--publish-service-requests``, their requests are sent to the service again (rosbag2's
player, Jazzy). Which topics and services: ``--topics``, ``--services``, ``--regex`` and the
excludes, as rosbag2's ``allow_topic`` decides.

`ros2 bag play` runs a node ``rosbag2_player`` and logs rosbag2's lines; in a terminal SPACE
pauses and resumes, CURSOR_RIGHT plays the next message, CURSOR_UP/DOWN change the rate by 10%.
`rosbag play` prints ROS 1's lines; SPACE pauses and ``s`` steps, as ROS 1's rosbag did.
"""

from __future__ import annotations

import re
import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

import rclpy.logging
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rclpy.serialization import deserialize_message

from ros2cmd.bag.info import is_service_event_topic, service_name, service_type
from ros2cmd.bag.keyboard import Keyboard
from ros2cmd.bag.record import message_class
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name
from ros2cmd.typenames import load_type
from ros_tutorials_common.wait import spin_until
from rosbag2.errors import shown
from rosbag2.mcap_file import BagMessage
from rosbag2.metadata import NS, TopicInfo
from rosbag2.reader import BagReader

ADVERTISE_WAIT = 0.2  # ROS 1's "Waiting 0.2 seconds after advertising topics"
MATCH_TIMEOUT = 5.0  # seconds: the longest play waits to meet the subscribers already running
PUBLISHER_DEPTH = 100
# Publishers (and service clients) one play makes: each costs about 70 KiB and a DDS
# endpoint that every participant on the machine is told of.
MAX_PUBLISHERS = 1000
ACK_TIMEOUT = 5.0  # at the end: how long reliable subscribers get to take the last messages
MIN_LOOP_PERIOD = 0.1  # seconds: --loop plays a bag at most this often
STEP = 0.05  # seconds: the longest the loop waits before looking at keys and services again


@dataclass
class PlayOptions:
    rate: float = 1.0
    loop: bool = False
    topics: list[str] | None = None  # None: every topic (rosbag); [] too (ros2 bag)
    services: list[str] = field(default_factory=list)  # their /_service_event topics
    regex: str = ""
    exclude_regex: str = ""
    exclude_topics: list[str] = field(default_factory=list)
    exclude_services: list[str] = field(default_factory=list)  # /_service_event topics
    start_offset: float = 0.0
    remaps: dict[str, str] | None = None
    wait_for_subscribers: bool = False
    delay: float = 0.0
    start_paused: bool = False
    keyboard: bool = True
    playback_duration: float = -1.0  # seconds; negative: to the end
    playback_until: int = -1  # ns since the epoch; negative: to the end
    wait_acked_timeout: int = -1  # ms (--wait-for-all-acked); 0 forever; negative: no wait
    publish_service_requests: bool = False
    client_introspection: bool = False  # --service-requests-source client_introspection
    node_name: str = "rosbag2_player"
    ros1: bool = False  # `rosbag play`: ROS 1's lines and keys

    def __post_init__(self) -> None:
        self.services = [absolute_name(s) for s in self.services]
        self.exclude_topics = [absolute_name(t) for t in self.exclude_topics]
        self.exclude_services = [absolute_name(s) for s in self.exclude_services]


def parse_remap(text: str) -> tuple[str, str]:
    """'FROM:=TO' -> ('/FROM', '/TO')."""
    source, separator, target = text.partition(":=")
    if not separator or not source.strip() or not target.strip():
        raise ToolError(f"invalid remap '{text}': expected FROM:=TO, e.g. /chatter:=/chatter2")
    return absolute_name(source.strip()), absolute_name(target.strip())


def recorded_qos(topic: TopicInfo) -> QoSProfile:
    """What the recorded publishers offered, if they agreed (rosbag2's adapt_offer_...)."""
    qos = QoSProfile(depth=PUBLISHER_DEPTH)
    profiles = topic.offered_qos_profiles
    reliabilities = {p.get("reliability") for p in profiles}
    durabilities = {p.get("durability") for p in profiles}
    if reliabilities == {"best_effort"}:
        qos.reliability = ReliabilityPolicy.BEST_EFFORT
    if durabilities == {"transient_local"}:
        qos.durability = DurabilityPolicy.TRANSIENT_LOCAL
    return qos


def allow_topic(options: PlayOptions, is_service: bool, name: str) -> bool:
    """rosbag2's player filter (Jazzy's allow_topic): excludes first, then includes/regex."""
    excluded = options.exclude_services if is_service else options.exclude_topics
    if name in excluded:
        return False
    if options.exclude_regex and re.fullmatch(options.exclude_regex, name):
        return False
    included = options.services if is_service else (options.topics or [])
    if included or options.regex:
        if name in included:
            return True
        return bool(options.regex) and re.fullmatch(options.regex, name) is not None
    return True


class Clock:
    """Bag time against wall time: a rate, a pause, a jump (rosbag2's TimeControllerClock)."""

    def __init__(self, start: int, rate: float, paused: bool) -> None:
        self.rate = rate
        self.paused = paused
        self.jump(start)

    def jump(self, bag_time: int) -> None:
        self.anchor_bag, self.anchor_wall = bag_time, time.monotonic()

    def now(self) -> int:
        if self.paused:
            return self.anchor_bag
        return self.anchor_bag + int((time.monotonic() - self.anchor_wall) * self.rate * NS)

    def wall_until(self, bag_time: int) -> float:
        """Seconds of wall time until bag_time is due (inf while paused)."""
        if self.paused:
            return float("inf")
        return (bag_time - self.now()) / NS / self.rate

    def set_rate(self, rate: float) -> None:
        self.jump(self.now())
        self.rate = rate

    def pause(self) -> None:
        self.jump(self.now())
        self.paused = True

    def resume(self) -> None:
        self.jump(self.anchor_bag)
        self.paused = False


class Player:
    def __init__(self, graph: Graph, reader: BagReader, options: PlayOptions, node: Node) -> None:
        self.graph = graph
        self.reader = reader
        self.options = options
        self.node = node
        bag = reader.bag
        remaps = options.remaps or {}
        self.publishers: dict[str, Any] = {}
        self.clients: dict[str, tuple[Any, type]] = {}  # event topic -> (client, Event class)
        self.pending: list[Any] = []  # requests sent, answers not in yet
        self.warned: set[str] = set()
        requested = None
        if options.ros1 and options.topics is not None:
            requested = [absolute_name(t) for t in options.topics]
            for name in requested:
                if name not in bag.topics:
                    print(f"warning: {name} is not in the bag", file=sys.stderr, flush=True)
        chosen = []
        for name, topic in bag.topics.items():
            event = is_service_event_topic(name, topic.type)
            if options.ros1 and requested is not None and name not in requested:
                continue
            if not options.ros1 and not allow_topic(options, event, name):
                continue
            chosen.append((name, topic, event))
        if len(chosen) > MAX_PUBLISHERS:
            raise ToolError(
                f"{shown(bag.path)}: {len(chosen)} topics to play; play makes at most "
                f"{MAX_PUBLISHERS} publishers: choose topics with --topics"
            )
        classes: dict[str, type | ToolError] = {}  # by type name: each looked up once
        for name, topic, event in chosen:
            if event and options.publish_service_requests:
                self._add_client(name, topic)
                continue
            if topic.type not in classes:
                try:
                    classes[topic.type] = message_class(topic.type)
                except ToolError as error:
                    classes[topic.type] = error
            msg_type = classes[topic.type]
            if isinstance(msg_type, ToolError):
                self.warn(
                    f"not playing {name}: {msg_type}",
                    f"Ignoring a topic '{name}', reason: {msg_type}.",
                )
                continue
            self.publishers[name] = node.create_publisher(
                msg_type, remaps.get(name, name), recorded_qos(topic)
            )
        if not self.publishers and not self.clients:
            raise ToolError(f"{bag.path}: no topic to play (of {len(bag.topics)} in the bag)")
        self.start = bag.start + int(options.start_offset * NS)
        self.until = self._until()
        self.clock = Clock(self.start, options.rate, options.start_paused)
        self.published = 0

    def _add_client(self, name: str, topic: TopicInfo) -> None:
        service = service_name(name)
        try:
            srv_type = load_type(service_type(topic.type), ("srv",))
        except ToolError as error:
            self.warn(
                f"not playing {service}: {error}",
                f"Ignoring a service '{service}', reason: {error}.",
            )
            return
        client = self.node.create_client(srv_type, service)
        self.clients[name] = (client, srv_type.Event)  # type: ignore[attr-defined]

    def _until(self) -> int:
        """rosbag2's play-until timestamp (ns; -1: to the end)."""
        duration, until = self.options.playback_duration, self.options.playback_until
        if duration < 0 and until < 0:
            return -1
        from_duration = 0 if duration == 0 else self.start + int(duration * NS)
        return max(from_duration, until)

    # What the user sees

    def info(self, text: str) -> None:
        self.node.get_logger().info(text)

    def warn(self, ros1_text: str, ros2_text: str) -> None:
        if self.options.ros1:
            print(f"warning: {ros1_text}", file=sys.stderr, flush=True)
        else:
            self.node.get_logger().warning(ros2_text)

    def warn_once(self, text: str) -> None:
        if text not in self.warned:
            self.warned.add(text)
            rclpy.logging.get_logger("rosbag2_transport").warning(text)

    # Playing

    def wait_for_subscribers(self) -> None:
        for name, publisher in self.publishers.items():
            self.graph.wait_for(
                lambda p=publisher: p.get_subscription_count() > 0,
                f"no subscriber on {publisher.topic_name} (for {name})",
            )

    def wait_for_matches(self) -> None:
        """Where subscribers of the played topics run already, wait until each publisher is
        matched with them (at most MATCH_TIMEOUT), so that the first messages reach them."""
        self.graph.settle()  # the subscribers that run now are in the graph
        wanted = {
            publisher: self.node.count_subscribers(publisher.topic_name)
            for publisher in self.publishers.values()
        }
        if not any(wanted.values()):
            return

        def missing() -> list[str]:
            return [
                publisher.topic_name
                for publisher, count in wanted.items()
                if publisher.get_subscription_count() < count
            ]

        if spin_until(self.graph.executor, lambda: not missing(), MATCH_TIMEOUT):
            return
        text = (
            f"not yet matched with every subscriber of {', '.join(missing())} after "
            f"{MATCH_TIMEOUT:g} s (an incompatible QoS?); playing: they may miss messages"
        )
        self.warn(text, text)

    def messages(self) -> Iterator[BagMessage]:
        topics = [*self.publishers, *self.clients]
        yield from self.reader.messages(topics, self.start)

    def _wait(self, timeout: float, keyboard: Keyboard) -> str:
        """Spin (service answers, discovery) up to timeout seconds; the key pressed, if any."""
        self.graph.spin_once(max(0.0, min(timeout, STEP)))
        return keyboard.wait(0) if keyboard.active else ""

    def _key(self, key: str, message: BagMessage) -> bool:
        """Act on a key; True if the message is to be published now (a step while paused)."""
        clock, ros1 = self.clock, self.options.ros1
        if key == "SPACE":
            if clock.paused:
                clock.resume()
                self._status("RUNNING", message) if ros1 else self.info("Resuming play.")
            else:
                clock.pause()
                self._status("PAUSED", message) if ros1 else self.info("Pausing play.")
        elif key == ("s" if ros1 else "CURSOR_RIGHT"):
            if clock.paused:
                clock.jump(message.log_time)
                return True
            if not ros1:
                self.node.get_logger().warning("Called play next, but not in paused state.")
        elif key in ("CURSOR_UP", "CURSOR_DOWN") and not ros1:
            rate = clock.rate + (0.1 if key == "CURSOR_UP" else -0.1)
            if rate > 0:
                clock.set_rate(rate)
                self.info(f"Set rate to {rate:g}")
            else:
                self.node.get_logger().warning(f"Failed to set rate to invalid value {rate:g}")
        return False

    def play_once(self, keyboard: Keyboard) -> bool:
        """One pass through the bag, in bag time; False if stopped by the play-until time."""
        self.clock.jump(self.start)
        for message in self.messages():
            if self.until == 0 or (self.until > -1 and message.log_time > self.until):
                return False
            stepped = False
            while not stepped:
                remaining = self.clock.wall_until(message.log_time)
                if remaining <= 0:
                    break
                key = self._wait(remaining, keyboard)
                if key:
                    stepped = self._key(key, message)
            self._send(message)
            if stepped and self.options.ros1:
                self._status("PAUSED", message)
        return True

    def _send(self, message: BagMessage) -> None:
        client = self.clients.get(message.topic)
        if client is None:
            self.publishers[message.topic].publish(message.data)
            self.published += 1
            return
        self._send_request(message, *client)

    def _send_request(self, message: BagMessage, client: Any, event_type: type) -> None:
        """A recorded request, sent to the service again (rosbag2's PlayerServiceClient)."""
        from service_msgs.msg import ServiceEventInfo

        event = deserialize_message(message.data, event_type)
        wanted = (
            ServiceEventInfo.REQUEST_SENT
            if self.options.client_introspection
            else ServiceEventInfo.REQUEST_RECEIVED
        )
        if event.info.event_type != wanted:
            return
        service = service_name(message.topic)
        if not client.service_is_ready():
            self.node.get_logger().error(
                f"Service request hasn't been sent. The '{service}' service isn't ready !"
            )
            return
        if not event.request:
            side = "client" if self.options.client_introspection else "service side"
            self.warn_once(
                "Can't send service request. The configuration of introspection for "
                f"'{service}' was metadata only on {side}!"
            )
            return
        self.pending.append(client.call_async(event.request[0]))
        self.published += 1

    def _status(self, what: str, message: BagMessage) -> None:
        bag_time = message.log_time / NS
        elapsed = (message.log_time - self.reader.bag.start) / NS
        total = self.reader.bag.duration / NS
        print(
            f"\r [{what}]  Bag Time: {bag_time:.6f}   Duration: {elapsed:.6f} / {total:.6f}",
            end="",
            flush=True,
        )

    def finish(self) -> None:
        """Give reliable subscribers the last messages, and services their requests' answers,
        before the publishers go away."""
        timeout = ACK_TIMEOUT
        if self.options.wait_acked_timeout > 0:
            timeout = self.options.wait_acked_timeout / 1000
        elif self.options.wait_acked_timeout == 0:
            timeout = float("inf")
        for publisher in self.publishers.values():
            publisher.wait_for_all_acked(Duration(seconds=min(timeout, 10**9)))
        deadline = time.monotonic() + ACK_TIMEOUT
        while any(not f.done() for f in self.pending) and time.monotonic() < deadline:
            self.graph.spin_once(STEP)


def play(graph: Graph, path: str, options: PlayOptions) -> None:
    if options.ros1:
        print(f"[ INFO] [{time.time():.9f}]: Opening {path}", flush=True)
    with BagReader(path) as reader:
        bag = reader.bag
        for warning in bag.warnings:
            print(f"warning: {warning}", file=sys.stderr, flush=True)
        if options.start_offset * NS > bag.duration:
            raise ToolError(
                f"--start-offset {options.start_offset:g} s is beyond the bag's end "
                f"({bag.duration / NS:.3f} s)"
            )
        node = graph.node
        if not options.ros1:
            # rosbag2's player is a node of the graph, named rosbag2_player.
            node = Node(options.node_name, context=graph.node.context)
            graph.executor.add_node(node)
        try:
            _play(graph, reader, options, node)
        finally:
            if node is not graph.node:
                graph.executor.remove_node(node)
                node.destroy_node()


def _play(graph: Graph, reader: BagReader, options: PlayOptions, node: Node) -> None:
    player = Player(graph, reader, options, node)
    if not options.ros1:
        player.info(f"Set rate to {options.rate:g}")
        if options.keyboard:
            player.info("Adding keyboard callbacks.")
            for key, what in (
                ("SPACE", "Pause/Resume"),
                ("CURSOR_RIGHT", "Play Next Message"),
                ("CURSOR_UP", "Increase Rate 10%"),
                ("CURSOR_DOWN", "Decrease Rate 10%"),
            ):
                player.info(f"Press {key} for {what}")
    if options.wait_for_subscribers:
        print("Waiting for a subscriber on each topic...", flush=True)
        player.wait_for_subscribers()
    if options.ros1:
        print(f"Waiting {ADVERTISE_WAIT} seconds after advertising topics...", end="", flush=True)
        time.sleep(ADVERTISE_WAIT)
    # Discovery must join the new publishers to the subscribers already waiting, or the first
    # messages go to no one (a fixed wait is too short on a busy machine).
    player.wait_for_matches()
    if options.ros1:
        print(" done.", flush=True)
    else:
        player.info(f"Playback until timestamp: {player.until}")
    keyboard = Keyboard(enabled=options.keyboard)
    try:
        if keyboard.active and options.ros1:
            print("\nHit space to toggle paused, or 's' to step.", flush=True)
        while True:
            began = time.monotonic()
            if options.delay > 0:
                if not options.ros1:
                    player.info(f"Sleep {int(options.delay * NS)} ns")
                time.sleep(options.delay)
            reached_end = player.play_once(keyboard)
            if not (options.loop and reached_end):
                break
            # A bag of one instant would otherwise be published in a tight loop.
            time.sleep(max(0.0, MIN_LOOP_PERIOD - (time.monotonic() - began)))
        player.finish()
    except KeyboardInterrupt:
        if options.ros1:
            raise
        player.info("Stopping playback.")  # rosbag2: Ctrl-C stops the playback, exit 0
        return
    finally:
        keyboard.restore()
    if options.ros1:
        print(f"\nDone: {player.published} messages published.", flush=True)
