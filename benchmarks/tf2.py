"""tf2: a lookup through a chain of frames, and what a TransformListener costs in CPU.

- ``lookup_transform`` (tf2_ros.Buffer, the tf2_py core) from the end of a 10-frame chain to
  its root, at a time between two stamps of every frame (interpolated, slerped), p50 and p99
  of single calls; the baseline is the floor: numpy composing the same ten 4x4 matrices.
- A TransformListener's CPU with 100 frames at 100 Hz: a broadcaster process sends one
  TFMessage of 100 transforms every 10 ms; the listener (a Buffer and its listener, spun) runs
  in a process of its own, measured from /proc over 10 s after a warm-up. The baseline is a
  bare rclpy subscription to /tf with an empty callback, the two side by side over the same
  seconds: what receiving the messages costs at all.
- The listener's own work on one such message in this process (its callback filling the
  Buffer), against rclpy's deserialisation of the message, which both pay: the share the
  listener adds, without the machine's load in it.
"""

from __future__ import annotations

import math
import os
import time

import numpy as np

from benchmarks.common import Row, fmt_us, p50, p99, python, smoke, start, stop, wait_for_lines

CHAIN = 10
CALLS = smoke(5000, 50)


def _chain_buffer():
    from geometry_msgs.msg import TransformStamped
    from rclpy.time import Time

    from tf2_ros.buffer import Buffer

    buffer = Buffer()
    matrices = []
    for number in range(1, CHAIN + 1):
        for seconds in (10, 11):
            message = TransformStamped()
            message.header.frame_id = f"frame{number - 1}"
            message.child_frame_id = f"frame{number}"
            message.header.stamp = Time(seconds=seconds).to_msg()
            angle = 0.1 * number + 0.05 * (seconds - 10)
            message.transform.translation.x = 1.0
            message.transform.translation.y = 0.1 * number
            message.transform.rotation.z = math.sin(angle / 2)
            message.transform.rotation.w = math.cos(angle / 2)
            buffer.set_transform(message, "bench")
        angle = 0.1 * number + 0.025
        matrix = np.eye(4)
        matrix[:2, :2] = [[math.cos(angle), -math.sin(angle)], [math.sin(angle), math.cos(angle)]]
        matrix[:3, 3] = [1.0, 0.1 * number, 0.0]
        matrices.append(matrix)
    return buffer, matrices


def _timed(call, calls: int = CALLS) -> list[float]:
    for _ in range(200):  # warm-up
        call()
    samples = []
    clock = time.perf_counter
    for _ in range(calls):
        began = clock()
        call()
        samples.append(clock() - began)
    return samples


def lookup_chain() -> list[Row]:
    from rclpy.time import Time

    buffer, matrices = _chain_buffer()
    when = Time(seconds=10, nanoseconds=500_000_000)
    looked = buffer.lookup_transform("frame0", f"frame{CHAIN}", when)
    expected = np.linalg.multi_dot(matrices)
    t = looked.transform.translation
    assert np.allclose([t.x, t.y, t.z], expected[:3, 3]), "the lookup disagrees with numpy"

    def compose() -> np.ndarray:
        result = matrices[0]
        for matrix in matrices[1:]:
            result = result @ matrix
        return result

    ours = _timed(lambda: buffer.lookup_transform("frame0", f"frame{CHAIN}", when))
    core = _timed(lambda: buffer._lookup("frame0", f"frame{CHAIN}", when.nanoseconds))
    floor = _timed(compose)
    return [
        Row(
            f"tf2: lookup_transform, {CHAIN}-frame chain, interpolated (p50/p99)",
            f"{fmt_us(p50(ours))} / {fmt_us(p99(ours))}",
            f"{fmt_us(p50(floor))} / {fmt_us(p99(floor))} (numpy, 10 4x4 @)",
            p50(ours) / p50(floor),
        ),
        Row(
            "tf2: the same, the walk only (no TransformStamped built) (p50/p99)",
            f"{fmt_us(p50(core))} / {fmt_us(p99(core))}",
            f"{fmt_us(p50(floor))} / {fmt_us(p99(floor))} (numpy)",
            p50(core) / p50(floor),
        ),
    ]


BROADCASTER = """
import math, rclpy
from geometry_msgs.msg import TransformStamped
from tf2_msgs.msg import TFMessage
from tf2_ros import TransformBroadcaster
rclpy.init()
node = rclpy.create_node('bench_broadcaster')
broadcaster = TransformBroadcaster(node)
def tick():
    now = node.get_clock().now().to_msg()
    transforms = []
    for number in range(100):
        t = TransformStamped()
        t.header.stamp = now
        t.header.frame_id = 'world'
        t.child_frame_id = f'frame{number}'
        t.transform.translation.x = float(number)
        t.transform.rotation.w = 1.0
        transforms.append(t)
    broadcaster.sendTransform(transforms)
node.create_timer(0.01, tick)
print('broadcasting', flush=True)
rclpy.spin(node)
"""

LISTENER = """
import rclpy, sys
from rclpy.time import Time
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener
rclpy.init()
node = rclpy.create_node('bench_listener')
buffer = Buffer()
listener = TransformListener(buffer, node)
def check():
    if buffer.can_transform('world', 'frame99', Time()):
        print('listening', flush=True)
node.create_timer(0.5, check)
rclpy.spin(node)
"""

BARE = """
import rclpy
from rclpy.qos import QoSProfile
from tf2_msgs.msg import TFMessage
rclpy.init()
node = rclpy.create_node('bench_bare')
seen = []
def heard(message):
    if not seen:
        seen.append(1)
        print('listening', flush=True)
node.create_subscription(TFMessage, '/tf', heard, QoSProfile(depth=100))
node.create_timer(0.5, lambda: None)  # the listener's check timer, so both wake alike
rclpy.spin(node)
"""


def _cpu_seconds(pid: int) -> float:
    with open(f"/proc/{pid}/stat") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _listeners_cpu(scripts: list[str], seconds: float) -> list[float]:
    """The share of one core each SCRIPT's process takes while they receive the broadcaster
    side by side, over the same SECONDS (a loaded machine slows both alike)."""
    processes = [start(python("-c", script)) for script in scripts]
    try:
        for process in processes:
            if not wait_for_lines(process, lambda line: "listening" in line, timeout=60):
                raise RuntimeError("a listener never received the frames")
        time.sleep(2.0)  # warm-up: discovery settled, caches full
        before, began = [_cpu_seconds(p.pid) for p in processes], time.monotonic()
        time.sleep(seconds)
        elapsed = time.monotonic() - began
        return [(_cpu_seconds(p.pid) - b) / elapsed for p, b in zip(processes, before, strict=True)]
    finally:
        for process in processes:
            stop(process)


def listener_cpu(seconds: float = smoke(10.0, 1.0)) -> list[Row]:
    broadcaster = start(python("-c", BROADCASTER))
    try:
        if not wait_for_lines(broadcaster, lambda line: "broadcasting" in line, timeout=60):
            raise RuntimeError("the broadcaster did not start")
        listener, bare = _listeners_cpu([LISTENER, BARE], seconds)
    finally:
        stop(broadcaster)
    return [
        Row(
            f"tf2: TransformListener CPU, 100 frames at 100 Hz (1 message / 10 ms), {seconds:g} s "
            "side by side",
            f"{listener * 100:.0f} % of a core",
            f"{bare * 100:.0f} % (bare rclpy subscription to /tf)",
            listener / bare if bare else None,
            "ratio <= 1.20",
            bool(bare) and listener / bare <= 1.20,
        )
    ]


def callback_cost(messages: int = smoke(50, 5), rounds: int = smoke(30, 2)) -> list[Row]:
    """The listener's callback on a TFMessage of 100 transforms against rclpy deserialising
    it (p50 of ROUNDS rounds of MESSAGES messages, each round newer stamps)."""
    from geometry_msgs.msg import TransformStamped
    from rclpy.serialization import deserialize_message, serialize_message
    from tf2_msgs.msg import TFMessage

    from tf2_ros.buffer import Buffer
    from tf2_ros.transform_listener import TransformListener

    listener = TransformListener.__new__(TransformListener)  # its callback, no node
    listener.buffer = Buffer()
    transforms = []
    for number in range(100):
        t = TransformStamped()
        t.header.frame_id, t.child_frame_id = "world", f"frame{number}"
        t.transform.translation.x, t.transform.rotation.w = float(number), 1.0
        transforms.append(t)
    raw = serialize_message(TFMessage(transforms=transforms))
    batch = [deserialize_message(raw, TFMessage) for _ in range(messages)]
    stamp = 10**9
    callback, deserialize = [], []
    for _ in range(rounds):
        began = time.perf_counter()
        for _ in range(messages):
            deserialize_message(raw, TFMessage)
        deserialize.append((time.perf_counter() - began) / messages)
        for message in batch:
            stamp += 10_000_000
            for t in message.transforms:
                t.header.stamp.sec, t.header.stamp.nanosec = divmod(stamp, 10**9)
        began = time.perf_counter()
        for message in batch:
            listener.callback(message)
        callback.append((time.perf_counter() - began) / messages)
    ours, theirs = p50(callback), p50(deserialize)
    return [
        Row(
            "tf2: the listener's callback on one TFMessage of 100 transforms (p50)",
            fmt_us(ours),
            f"{fmt_us(theirs)} (rclpy deserialising it)",
            ours / theirs,
        )
    ]
