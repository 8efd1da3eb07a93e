"""turtlesim figures: the update rate and CPU of turtlesim_node, idle and with 10 turtles
driven at 10 Hz; headless always, and windowed too when a display exists (e.g. under Xvfb).

The period is measured where a user sees it: the arrival times of turtle1/pose (published
once per update) in a subscriber in this process, so DDS delivery jitter is included. The
baseline is a bare rclpy node publishing a Pose from a 16 ms timer, measured the same way.
CPU is the node process's user + system time over the measured window.
"""

from __future__ import annotations

import itertools
import os
import threading
import time

import rclpy
from geometry_msgs.msg import Twist
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import Spawn

from benchmarks.common import Row, fmt_ms, p99, python, smoke, start, stop, wait_for_lines
from ros_tutorials_common import wait

PERIOD = 0.016
TURTLES = 10
DRIVE_HZ = 10.0
HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
BARE_TIMER = (
    "import rclpy\n"
    "from turtlesim.msg import Pose\n"
    "rclpy.init()\n"
    "node = rclpy.create_node('bare_timer')\n"
    "pub = node.create_publisher(Pose, 'turtle1/pose', 7)\n"
    "node.create_timer(0.016, lambda: pub.publish(Pose()))\n"
    "print('Spawning turtle [turtle1] (bare timer)', flush=True)\n"
    "try:\n"
    "    rclpy.spin(node)\n"
    "except KeyboardInterrupt:\n"
    "    pass\n"
)


def _cpu_seconds(pid: int) -> float:
    with open(f"/proc/{pid}/stat") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


class Bench:
    """This process's node: spawns and drives turtles, times turtle1's poses."""

    def __init__(self, context) -> None:
        self.node = Node("turtlesim_bench", context=context)
        self.executor = SingleThreadedExecutor(context=context)
        self.executor.add_node(self.node)
        self.arrivals: list[float] = []
        self.node.create_subscription(
            Pose, "/turtle1/pose", lambda _msg: self.arrivals.append(time.monotonic()), 100
        )

    def spin_for(self, seconds: float) -> None:
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            self.executor.spin_once(timeout_sec=0.05)

    def spin_until(self, condition, timeout: float = 60.0) -> None:
        if not wait.spin_until(self.executor, condition, timeout, period=0.05):
            raise RuntimeError("turtlesim benchmark: timed out")

    def spawn(self, count: int) -> list[str]:
        client = self.node.create_client(Spawn, "/spawn")
        self.spin_until(client.service_is_ready)
        names = ["turtle1"]
        for i in range(1, count):
            future = client.call_async(Spawn.Request(x=1.0 + i, y=1.0 + 0.5 * i, theta=0.0))
            self.spin_until(future.done)
            names.append(future.result().name)
        return names

    def drive(self, names: list[str]) -> None:
        """Each turtle in a circle, one Twist per turtle DRIVE_HZ times a second."""
        publishers = [self.node.create_publisher(Twist, f"/{name}/cmd_vel", 7) for name in names]
        twist = Twist()
        twist.linear.x, twist.angular.z = 0.5, 0.5
        self.node.create_timer(1 / DRIVE_HZ, lambda: [p.publish(twist) for p in publishers])

    def measure(self, pid: int, seconds: float) -> tuple[float, float, float]:
        """(mean period, p99 jitter, CPU share of one core) over the next seconds."""
        self.spin_for(1.0)  # settle
        self.arrivals.clear()
        cpu, wall = _cpu_seconds(pid), time.monotonic()
        self.spin_for(seconds)
        cpu, wall = _cpu_seconds(pid) - cpu, time.monotonic() - wall
        times = list(self.arrivals)
        periods = [b - a for a, b in itertools.pairwise(times)]
        mean = (times[-1] - times[0]) / (len(times) - 1)
        return mean, p99([abs(p - PERIOD) for p in periods]), cpu / wall

    def close(self) -> None:
        self.executor.shutdown()
        self.node.destroy_node()


def _run(command: list[str], env: dict, loaded: bool, seconds: float) -> tuple:
    proc = start(command, env=env)
    context = rclpy.Context()
    rclpy.init(context=context)
    bench = Bench(context)
    try:
        if not wait_for_lines(proc, lambda line: "Spawning turtle [turtle1]" in line, 60):
            raise RuntimeError(f"{command} did not start")
        # its further log lines are not needed, but the pipe must never fill
        threading.Thread(target=proc.stdout.read, daemon=True).start()
        bench.spin_until(lambda: len(bench.arrivals) > 10)
        if loaded:
            bench.drive(bench.spawn(TURTLES))
        return bench.measure(proc.pid, seconds)
    finally:
        bench.close()
        context.try_shutdown()
        stop(proc)


def _row(label: str, sim: tuple, bare: tuple) -> Row:
    mean, jitter, _ = sim
    error = abs(mean - PERIOD) / PERIOD
    return Row(
        f"turtlesim update period mean / p99 jitter, {label}",
        f"{mean * 1e3:.3f} ms / {fmt_ms(jitter)}",
        f"{bare[0] * 1e3:.3f} ms / {fmt_ms(bare[1])} (bare rclpy 16 ms timer)",
        mean / bare[0],
        "mean within 1 % of 16 ms",
        error <= 0.01,
    )


def update_rate(seconds: float = smoke(20.0, 2.0)) -> list[Row]:
    node = python("-m", "ros_tutorials_turtlesim.turtlesim_node")
    bare = _run(python("-c", BARE_TIMER), HEADLESS, loaded=False, seconds=seconds)
    modes = [("headless", HEADLESS)]
    if os.environ.get("DISPLAY"):
        modes.append((f"window on DISPLAY={os.environ['DISPLAY']}", {}))
    rows = []
    for mode, env in modes:
        idle = _run(node, env, loaded=False, seconds=seconds)
        loaded = _run(node, env, loaded=True, seconds=seconds)
        rows.append(_row(f"{mode}, 1 turtle idle", idle, bare))
        rows.append(_row(f"{mode}, {TURTLES} turtles driven at 10 Hz", loaded, bare))
        rows.append(
            Row(
                f"turtlesim CPU (one core = 100 %), {mode}: idle / {TURTLES} turtles at 10 Hz",
                f"{idle[2] * 100:.1f} % / {loaded[2] * 100:.1f} %",
                f"{bare[2] * 100:.1f} % (bare rclpy 16 ms timer)",
                idle[2] / bare[2] if bare[2] else None,
            )
        )
    return rows


SCALE = smoke((50, 100, 200), (5, 10))  # turtles, spawned one after another, none driven


def many_turtles(seconds: float = smoke(5.0, 1.0)) -> list[Row]:
    """How many turtles one headless turtlesim keeps at 62.5 Hz, and how long /reset takes
    with the most of them (the limit is one core: rclpy's executor and the updates)."""
    from std_srvs.srv import Empty

    proc = start(python("-m", "ros_tutorials_turtlesim.turtlesim_node"), env=HEADLESS)
    context = rclpy.Context()
    rclpy.init(context=context)
    bench = Bench(context)
    rows = []
    try:
        if not wait_for_lines(proc, lambda line: "Spawning turtle [turtle1]" in line, 60):
            raise RuntimeError("turtlesim did not start")
        threading.Thread(target=proc.stdout.read, daemon=True).start()
        bench.spin_until(lambda: len(bench.arrivals) > 10)
        spawn = bench.node.create_client(Spawn, "/spawn")
        bench.spin_until(spawn.service_is_ready)
        count = 1
        for target in SCALE:
            while count < target:
                future = spawn.call_async(
                    Spawn.Request(x=1.0 + count % 9, y=1.0 + count // 9 % 9, theta=0.0)
                )
                bench.spin_until(future.done)
                count += 1
            mean, _, cpu = bench.measure(proc.pid, seconds)
            rows.append(
                Row(
                    f"turtlesim with {target} turtles (headless, none driven): turtle1/pose "
                    "rate, CPU",
                    f"{1 / mean:.1f} Hz, {cpu * 100:.0f} %",
                    "62.5 Hz (one update every 16 ms)",
                    (1 / mean) / 62.5,
                    "62.5 Hz",
                    abs(mean - PERIOD) / PERIOD <= 0.01,
                )
            )
        reset = bench.node.create_client(Empty, "/reset")
        started = time.monotonic()
        future = reset.call_async(Empty.Request())
        bench.spin_until(future.done)
        took = time.monotonic() - started
        rows.append(Row(f"turtlesim /reset with {SCALE[-1]} turtles", f"{took:.2f} s"))
        return rows
    finally:
        bench.close()
        context.try_shutdown()
        stop(proc)
