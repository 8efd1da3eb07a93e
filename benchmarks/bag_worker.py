"""Child processes of the bag benchmarks.

    python -m benchmarks.bag_worker publish SECONDS   1 kHz MsgTutorial + 30 Hz 1 MB Image
    python -m benchmarks.bag_worker listen COUNT      receive COUNT messages, note arrival times
    python -m benchmarks.bag_worker bare              a raw subscription that only counts
    python -m benchmarks.bag_worker publish_many N SECONDS   N topics of MsgTutorial at 1 kHz each
    python -m benchmarks.bag_worker bare_many N       a plain rclpy subscriber per topic, counting

Each prints one JSON line on stdout when done ("ready" lines before that).
"""

from __future__ import annotations

import json
import os
import signal
import sys
import time

import rclpy
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.qos import HistoryPolicy, QoSProfile
from rclpy.signals import SignalHandlerOptions
from ros_tutorials_interfaces.msg import MsgTutorial
from sensor_msgs.msg import Image

from ros_tutorials_common.ros import init

TUTORIAL_TOPIC, IMAGE_TOPIC = "/bench_tutorial", "/bench_image"
TUTORIAL_HZ, IMAGE_HZ = 1000.0, 30.0
IMAGE_SIDE = 1024  # 1024 x 1024 mono8: 1 MiB of pixels
QOS = QoSProfile(depth=1000)
RECORDER_QOS = QoSProfile(depth=1000, history=HistoryPolicy.KEEP_ALL)  # as rosbag record


def publish(seconds: float) -> dict:
    node = Node("bag_bench_publisher")
    tutorial = node.create_publisher(MsgTutorial, TUTORIAL_TOPIC, QOS)
    image_pub = node.create_publisher(Image, IMAGE_TOPIC, QOS)
    image = Image(height=IMAGE_SIDE, width=IMAGE_SIDE, encoding="mono8", step=IMAGE_SIDE)
    image.data = bytes(IMAGE_SIDE * IMAGE_SIDE)
    print("ready", flush=True)
    deadline = time.monotonic() + 120
    while tutorial.get_subscription_count() < 1 or image_pub.get_subscription_count() < 1:
        if time.monotonic() > deadline:
            raise SystemExit("no subscriber within 120 s")
        time.sleep(0.01)
    time.sleep(1.0)  # the recorder prints and settles after subscribing
    print("publishing", flush=True)
    counts = {"tutorial": 0, "image": 0}
    start = time.monotonic()
    next_tutorial = next_image = start
    while True:
        now = time.monotonic()
        if now - start >= seconds:
            break
        if now >= next_tutorial:
            msg = MsgTutorial(data=counts["tutorial"])
            msg.stamp = node.get_clock().now().to_msg()
            tutorial.publish(msg)
            counts["tutorial"] += 1
            next_tutorial += 1.0 / TUTORIAL_HZ
        if now >= next_image:
            image.header.stamp = node.get_clock().now().to_msg()
            image_pub.publish(image)
            counts["image"] += 1
            next_image += 1.0 / IMAGE_HZ
        wait = min(next_tutorial, next_image) - time.monotonic()
        if wait > 0:
            time.sleep(wait)
    for publisher in (tutorial, image_pub):
        publisher.wait_for_all_acked(Duration(seconds=30))
    counts["seconds"] = time.monotonic() - start
    return counts


def listen(count: int) -> dict:
    """Arrival times of the first COUNT messages on both topics, in order: the time DDS
    received each (rmw's received_timestamp), so this process's own lag does not count."""
    node = Node("bag_bench_listener")
    arrivals: list[tuple[str, int]] = []

    def arrived(data: bytes, info: dict) -> None:
        # The first bytes hold the stamp: they say which recorded message this is.
        arrivals.append((data[:16].hex(), info["received_timestamp"]))

    subscriptions = [
        node.create_subscription(msg_type, topic, arrived, RECORDER_QOS, raw=True)
        for topic, msg_type in ((TUTORIAL_TOPIC, MsgTutorial), (IMAGE_TOPIC, Image))
    ]
    print("ready", flush=True)
    deadline = time.monotonic() + 300
    try:  # until all arrived, or Ctrl-C (the benchmark's: the player has finished)
        while len(arrivals) < count and time.monotonic() < deadline:
            rclpy.spin_once(node, timeout_sec=0.1)
            # Take the rest of a burst directly, as the recorder does, so that this
            # listener keeps up and what is measured is the player.
            for subscription in subscriptions:
                while True:
                    with subscription.handle:
                        taken = subscription.handle.take_message(subscription.msg_type, True)
                    if taken is None:
                        break
                    arrived(*taken)
    except KeyboardInterrupt:
        pass
    return {"arrivals": arrivals}


def bare() -> dict:
    """The baseline of the recorder: the same subscriptions, counting, writing nothing."""
    node = Node("bag_bench_bare")
    counts = {TUTORIAL_TOPIC: 0, IMAGE_TOPIC: 0}

    def count(topic: str) -> None:
        counts[topic] += 1

    for topic, msg_type in ((TUTORIAL_TOPIC, MsgTutorial), (IMAGE_TOPIC, Image)):
        node.create_subscription(
            msg_type, topic, lambda _data, t=topic: count(t), RECORDER_QOS, raw=True
        )
    print("Subscribed to topic 'both'", flush=True)
    try:
        while True:
            rclpy.spin_once(node, timeout_sec=0.1)
    except KeyboardInterrupt:  # what has arrived still counts, as for the recorder
        deadline = time.monotonic() + 5
        while time.monotonic() < deadline:
            before = sum(counts.values())
            rclpy.spin_once(node, timeout_sec=0.01)
            if sum(counts.values()) == before:
                break
    return {"tutorial": counts[TUTORIAL_TOPIC], "image": counts[IMAGE_TOPIC]}


MANY_TOPIC = "/bench_many_{}"
MANY_SUBSCRIBERS = 2  # the recorder and the bare subscriber, in the same run


def publish_many(topics: int, seconds: float, part: int = 0, parts: int = 1) -> dict:
    """TOPICS topics at 1 kHz each (a burst of one message per topic every millisecond); with
    PARTS processes, this one publishes every PARTS-th topic from PART on."""
    node = Node(f"bag_bench_many_publisher_{part}")
    publishers = [
        node.create_publisher(MsgTutorial, MANY_TOPIC.format(i), QOS)
        for i in range(part, topics, parts)
    ]
    print("ready", flush=True)
    deadline = time.monotonic() + 120
    subscribers = int(os.environ.get("BENCH_SUBSCRIBERS", MANY_SUBSCRIBERS))
    while min(p.get_subscription_count() for p in publishers) < subscribers:
        if time.monotonic() > deadline:
            raise SystemExit("not every topic had its subscribers within 120 s")
        time.sleep(0.01)
    time.sleep(1.0)  # the recorder prints and settles after subscribing
    print("publishing", flush=True)
    sent = 0
    start = next_tick = time.monotonic()
    msg = MsgTutorial()
    while time.monotonic() - start < seconds:
        msg.stamp = node.get_clock().now().to_msg()
        msg.data = sent
        for publisher in publishers:
            publisher.publish(msg)
        sent += len(publishers)
        next_tick += 0.001
        wait = next_tick - time.monotonic()
        if wait > 0:
            time.sleep(wait)
    for publisher in publishers:
        publisher.wait_for_all_acked(Duration(seconds=30))
    elapsed = time.monotonic() - start
    return {"sent": sent, "seconds": elapsed, "rate": sent / elapsed / len(publishers)}


def bare_many(topics: int) -> dict:
    """The baseline: one plain rclpy subscription per topic (raw, as the recorder's), whose
    callback counts; spun by rclpy.spin."""
    node = Node("bag_bench_bare_many")
    received = [0]

    def count(_data: bytes) -> None:
        received[0] += 1

    for i in range(topics):
        node.create_subscription(MsgTutorial, MANY_TOPIC.format(i), count, RECORDER_QOS, raw=True)
    stopped: list[int] = []
    signal.signal(signal.SIGINT, lambda number, _frame: stopped.append(number))  # a flag only
    print("Subscribed", flush=True)
    while not stopped:
        rclpy.spin_once(node, timeout_sec=0.1)
    deadline = time.monotonic() + 5  # what has arrived still counts, as for the recorder
    while time.monotonic() < deadline:
        before = received[0]
        rclpy.spin_once(node, timeout_sec=0.05)
        if received[0] == before:
            break
    return {"received": received[0]}


def main() -> None:
    init([sys.argv[0]], signal_handler_options=SignalHandlerOptions.NO)
    kind = sys.argv[1]
    if kind == "publish":
        result = publish(float(sys.argv[2]))
    elif kind == "listen":
        result = listen(int(sys.argv[2]))
    elif kind == "publish_many":
        result = publish_many(int(sys.argv[2]), float(sys.argv[3]), *map(int, sys.argv[4:6]))
    elif kind == "bare_many":
        result = bare_many(int(sys.argv[2]))
    else:
        result = bare()
    print(json.dumps(result), flush=True)


if __name__ == "__main__":
    main()
