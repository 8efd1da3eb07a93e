"""Child processes of the topic benchmarks, tutorial code paths and bare rclpy side by side.

    python -m benchmarks.topic_worker latency {tutorial,bare} COUNT
    python -m benchmarks.topic_worker publish {tutorial,bare} RATE_HZ SECONDS [TOPIC]
    python -m benchmarks.topic_worker subscribe {tutorial,bare} [TOPIC]

ROS arguments pass through (e.g. ``--ros-args --log-level warn``).

Each prints one JSON line with its figures on stdout. "tutorial" uses the tutorial nodes
(TopicPublisher.publish_message, TopicSubscriber.on_message with their logging);
"bare" does the same job with a plain rclpy publisher/subscription and no logging.
"""

from __future__ import annotations

import contextlib
import json
import time

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from ros_tutorials_interfaces.msg import MsgTutorial

from ros_tutorials_common.ros import init, user_args
from ros_tutorials_topic.publisher import TopicPublisher
from ros_tutorials_topic.subscriber import TopicSubscriber

TOPIC = "ros_tutorial_msg"
QUEUE_SIZE = 100  # the lesson's (ros_tutorials_topic/publisher.py: create_publisher(..., 100))


class BarePublisher(Node):
    def __init__(self, topic: str = TOPIC) -> None:
        super().__init__("bare_publisher")
        self.publisher = self.create_publisher(MsgTutorial, topic, QUEUE_SIZE)
        self.count = 0

    def publish_message(self) -> None:
        msg = MsgTutorial(stamp=self.get_clock().now().to_msg(), data=self.count)
        self.publisher.publish(msg)
        self.count += 1


def make_publisher(kind: str, topic: str = TOPIC) -> Node:
    if kind == "bare":
        return BarePublisher(topic)
    node = TopicPublisher(cli_args=["--ros-args", "-r", f"{TOPIC}:={topic}"])
    node.destroy_timer(node.timer)  # the benchmark drives publish_message itself
    return node


def make_subscriber(kind: str, on_received, topic: str = TOPIC) -> Node:
    if kind == "bare":
        node = Node("bare_subscriber")
        node.create_subscription(MsgTutorial, topic, on_received, QUEUE_SIZE)
        return node

    class Recording(TopicSubscriber):
        def on_message(self, msg: MsgTutorial) -> None:
            super().on_message(msg)
            on_received(msg)

    return Recording(cli_args=["--ros-args", "-r", f"{TOPIC}:={topic}"])


def latency(kind: str, count: int) -> dict:
    """Publish, then spin until the subscriber's callback has run; one process, two nodes."""
    received: list[MsgTutorial] = []
    publisher = make_publisher(kind)
    subscriber = make_subscriber(kind, received.append)
    executor = SingleThreadedExecutor()
    executor.add_node(publisher)
    executor.add_node(subscriber)
    while publisher.publisher.get_subscription_count() < 1:
        executor.spin_once(timeout_sec=0.01)
    samples = []
    for _ in range(count + 50):
        expected = len(received) + 1
        start = time.perf_counter()
        publisher.publish_message()
        while len(received) < expected:
            executor.spin_once(timeout_sec=1.0)
        samples.append(time.perf_counter() - start)
    return {"latency": samples[50:]}  # the first ones warm caches and allocators


def publish(kind: str, rate_hz: float, seconds: float, topic: str) -> dict:
    """Publish at rate_hz (0: as fast as possible) once a subscriber is matched."""
    node = make_publisher(kind, topic)
    while node.publisher.get_subscription_count() < 1:
        rclpy.spin_once(node, timeout_sec=0.01)
    start = time.monotonic()
    if rate_hz == 0:
        while time.monotonic() - start < seconds:
            node.publish_message()
    else:
        timer = node.create_timer(1.0 / rate_hz, node.publish_message)
        while time.monotonic() - start < seconds:
            rclpy.spin_once(node, timeout_sec=0.1)
        node.destroy_timer(timer)
    sent = node.count
    # Give a reliable subscriber time to fetch what it has not acknowledged yet.
    deadline = time.monotonic() + 5.0
    while time.monotonic() < deadline and not node.publisher.wait_for_all_acked(
        rclpy.duration.Duration(seconds=0.1)
    ):
        pass
    return {"sent": sent, "seconds": time.monotonic() - start}


def subscribe(kind: str, topic: str) -> dict:
    """Count what arrives until Ctrl-C: received, lost (gaps in data), receive times."""
    data: list[int] = []
    arrival: list[float] = []

    def on_received(msg: MsgTutorial) -> None:
        data.append(msg.data)
        arrival.append(time.monotonic())

    node = make_subscriber(kind, on_received, topic)
    print(json.dumps({"ready": True}), flush=True)
    with contextlib.suppress(KeyboardInterrupt, ExternalShutdownException):
        rclpy.spin(node)
    lost = (max(data) - min(data) + 1 - len(set(data))) if data else 0
    span = arrival[-1] - arrival[0] if len(arrival) > 1 else 0.0
    return {"received": len(data), "lost": lost, "span": span}


def main() -> int:
    init()
    verb, kind, *rest = user_args()
    if verb == "latency":
        result = latency(kind, int(rest[0]))
    elif verb == "publish":
        topic = rest[2] if len(rest) > 2 else TOPIC
        result = publish(kind, float(rest[0]), float(rest[1]), topic)
    else:
        result = subscribe(kind, rest[0] if rest else TOPIC)
    print(json.dumps(result), flush=True)
    rclpy.try_shutdown()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
