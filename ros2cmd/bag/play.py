"""`rosbag play BAG` / `ros2 bag play BAG`: publish a bag's messages as they were recorded.

Each message goes out as the bytes that were recorded (``publish`` of ``bytes`` is rclpy's
raw publish), at its recorded time relative to the first one, scaled by ``--rate``. Each
topic's publisher offers the reliability and durability its recorded publishers offered
(rosbag2 stores them as ``offered_qos_profiles``), so a latched topic is latched again.
A topic whose type is not installed here is skipped with a warning; the rest plays.

In a terminal, space pauses and resumes, and ``s`` publishes the next message while paused,
as ROS 1's rosbag play did.
"""

from __future__ import annotations

import contextlib
import os
import select
import sys
import termios
import time
import tty
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from rclpy.duration import Duration
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from ros2cmd.bag.storage import NS, BagMessage, BagReader, TopicInfo
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name
from ros2cmd.typenames import load_type

ADVERTISE_WAIT = 0.2  # ROS 1's "Waiting 0.2 seconds after advertising topics"
PUBLISHER_DEPTH = 100
ACK_TIMEOUT = 5.0  # at the end: how long reliable subscribers get to take the last messages
MIN_LOOP_PERIOD = 0.1  # seconds: --loop plays a bag at most this often


@dataclass
class PlayOptions:
    rate: float = 1.0
    loop: bool = False
    topics: list[str] | None = None
    start_offset: float = 0.0
    remaps: dict[str, str] | None = None
    wait_for_subscribers: bool = False


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


class _Keyboard:
    """Single key presses from a terminal (space, s), without echo; nothing otherwise."""

    def __init__(self) -> None:
        self.fd = -1
        self.saved: Any = None
        with contextlib.suppress(AttributeError, ValueError, OSError):
            if sys.stdin.isatty():
                self.fd = sys.stdin.fileno()
                self.saved = termios.tcgetattr(self.fd)
                tty.setcbreak(self.fd)

    @property
    def active(self) -> bool:
        return self.fd >= 0

    def wait(self, timeout: float) -> str:
        """The key pressed within timeout seconds ('' if none); sleeps without a terminal."""
        if not self.active:
            if timeout > 0:
                time.sleep(timeout)
            return ""
        ready, _, _ = select.select([self.fd], [], [], max(timeout, 0.0))
        return os.read(self.fd, 1).decode(errors="replace") if ready else ""

    def restore(self) -> None:
        if self.active:
            termios.tcsetattr(self.fd, termios.TCSADRAIN, self.saved)


class Player:
    def __init__(self, graph: Graph, reader: BagReader, options: PlayOptions) -> None:
        self.graph = graph
        self.reader = reader
        self.options = options
        bag = reader.bag
        remaps = options.remaps or {}
        wanted = list(bag.topics)
        if options.topics is not None:
            requested = [absolute_name(t) for t in options.topics]
            for name in requested:
                if name not in bag.topics:
                    print(f"warning: {name} is not in the bag", file=sys.stderr, flush=True)
            wanted = [t for t in wanted if t in requested]
        self.publishers: dict[str, Any] = {}
        for name in wanted:
            topic = bag.topics[name]
            try:
                msg_type = load_type(topic.type, ("msg",))
            except ToolError as error:
                print(f"warning: not playing {name}: {error}", file=sys.stderr, flush=True)
                continue
            self.publishers[name] = graph.node.create_publisher(
                msg_type, remaps.get(name, name), recorded_qos(topic)
            )
        if not self.publishers:
            raise ToolError(f"{bag.path}: no topic to play (of {len(bag.topics)} in the bag)")
        self.start = bag.start + int(options.start_offset * NS)
        self.published = 0

    def wait_for_subscribers(self) -> None:
        for name, publisher in self.publishers.items():
            self.graph.wait_for(
                lambda p=publisher: p.get_subscription_count() > 0,
                f"no subscriber on {publisher.topic_name} (for {name})",
            )

    def messages(self) -> Iterator[BagMessage]:
        yield from self.reader.messages(self.publishers, self.start)

    def play_once(self, keyboard: _Keyboard, state: dict[str, Any]) -> None:
        """One pass through the bag, in recorded time; pausing shifts the clock."""
        wall_start = time.monotonic()
        for message in self.messages():
            due = wall_start + (message.log_time - self.start) / NS / self.options.rate
            stepped = False
            while True:
                if state["paused"]:
                    key = keyboard.wait(0.1)
                    if key == " ":
                        state["paused"] = False
                        wall_start += time.monotonic() - state["paused_at"]
                        due = wall_start + (message.log_time - self.start) / NS / self.options.rate
                        self._status("RUNNING", message)
                    elif key == "s":
                        wall_start += time.monotonic() - state["paused_at"]
                        state["paused_at"] = time.monotonic()
                        stepped = True
                        break  # publish this one now, stay paused
                    continue
                remaining = due - time.monotonic()
                if remaining <= 0:
                    break
                key = keyboard.wait(min(remaining, 0.1))
                if key == " ":
                    state["paused"], state["paused_at"] = True, time.monotonic()
                    self._status("PAUSED", message)
            self.publishers[message.topic].publish(message.data)
            self.published += 1
            if stepped:
                self._status("PAUSED", message)

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
        """Give reliable subscribers the last messages before the publishers go away."""
        for publisher in self.publishers.values():
            publisher.wait_for_all_acked(Duration(seconds=ACK_TIMEOUT))


def play(graph: Graph, path: str, options: PlayOptions) -> None:
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
        player = Player(graph, reader, options)
        if options.wait_for_subscribers:
            print("Waiting for a subscriber on each topic...", flush=True)
            player.wait_for_subscribers()
        print(f"Waiting {ADVERTISE_WAIT} seconds after advertising topics...", end="", flush=True)
        time.sleep(ADVERTISE_WAIT)
        print(" done.", flush=True)
        keyboard = _Keyboard()
        try:
            if keyboard.active:
                print("\nHit space to toggle paused, or 's' to step.", flush=True)
            state: dict[str, Any] = {"paused": False, "paused_at": 0.0}
            while True:
                began = time.monotonic()
                player.play_once(keyboard, state)
                if not options.loop:
                    break
                # A bag of one instant would otherwise be published in a tight loop.
                time.sleep(max(0.0, MIN_LOOP_PERIOD - (time.monotonic() - began)))
            player.finish()
        finally:
            keyboard.restore()
    print(f"\nDone: {player.published} messages published.", flush=True)
