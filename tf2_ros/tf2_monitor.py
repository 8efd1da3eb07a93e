"""`ros2 run tf2_ros tf2_monitor [FRAMEA FRAMEB]`: how late transforms arrive.

As ROS 2 Jazzy's C++ tool: it listens to /tf and /tf_static and, every ten seconds or so,
prints each frame's average and maximum delay (receipt time minus stamp, over its last 1000
transforms) and the broadcasters' rate; given two frames, first the chain between them and the
delay of the transform from FRAMEA to FRAMEB ("Net delay"). Numbers print as C++'s default
stream does (6 significant digits). Other arguments: the usage line, status 255 (the C++
main's -1).
"""

from __future__ import annotations

import sys
from collections import deque
from collections.abc import Sequence

from rclpy.logging import get_logger
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from rclpy.time import Time
from tf2_msgs.msg import TFMessage

from ros_tutorials_common.ros import run_node, user_args
from ros_tutorials_common.shutdown import program_main
from tf2_py import TransformException
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener

AUTHORITY = "<no authority available>"  # ROS 2's /tf carries no broadcaster's name
KEPT = 1000  # delays kept per frame and per broadcaster
REPORT_EVERY = 21  # rounds of 0.5 s between two reports


class Monitor:
    """The delays seen on /tf and /tf_static, per child frame and per broadcaster."""

    def __init__(self, node: Node) -> None:
        self.node = node
        self.delays: dict[str, deque[float]] = {}
        self.authority_delays: dict[str, deque[float]] = {}
        self.authority_times: dict[str, deque[float]] = {}
        dynamic = QoSProfile(depth=100, durability=DurabilityPolicy.VOLATILE)
        static = QoSProfile(
            depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL, history=HistoryPolicy.KEEP_LAST
        )
        node.create_subscription(TFMessage, "/tf", self.callback, dynamic)
        node.create_subscription(TFMessage, "/tf_static", self.callback, static)

    def now(self) -> float:
        return self.node.get_clock().now().nanoseconds / 1e9

    def callback(self, message: TFMessage) -> None:
        total = 0.0
        for transform in message.transforms:
            stamp = transform.header.stamp
            offset = self.now() - (stamp.sec + stamp.nanosec * 1e-9)
            total += offset
            self.delays.setdefault(transform.child_frame_id, deque(maxlen=KEPT)).append(offset)
        average = total / max(1, len(message.transforms))
        self.authority_delays.setdefault(AUTHORITY, deque(maxlen=KEPT)).append(average)
        self.authority_times.setdefault(AUTHORITY, deque(maxlen=KEPT)).append(self.now())

    def report(self, chain: list[str] | None) -> str:
        lines = ["", "Frames:"]
        for frame in sorted(self.delays):
            if chain is not None and frame not in chain:
                continue
            delays = self.delays[frame]
            lines.append(
                f"Frame: {frame}, published by {AUTHORITY}, Average Delay: "
                f"{sum(delays) / len(delays):g}, Max Delay: {max(0.0, *delays):g}"
            )
        broadcasters = []
        for authority in sorted(self.authority_delays):
            delays = self.authority_delays[authority]
            times = self.authority_times[authority]
            frequency = len(times) / max(0.00000001, times[-1] - times[0])
            broadcasters.append(
                f"Node: {authority} {frequency:g} Hz, Average Delay: "
                f"{sum(delays) / len(delays):g} Max Delay: {max(0.0, *delays):g}"
            )
        print("\n".join(lines))
        print("\nAll Broadcasters:", file=sys.stderr)  # the C++ tool writes this to stderr
        return "\n".join(broadcasters)


class TransformMonitor(Node):
    """tf2_monitor's node, spun by ``run_node``: the C++ tool's loop (wait for the chain from
    FRAMEA to FRAMEB, then a round every 0.5 s and a report every ``REPORT_EVERY`` rounds) as a
    timer, the listener's subscriptions and the monitor's in the same spin."""

    def __init__(self, frames: list[str]) -> None:
        super().__init__("tf2_monitor_main")
        self.frames = frames
        self.buffer = Buffer(node=self)
        self.monitor = Monitor(self)
        self.listener = TransformListener(self.buffer, self)
        self.chain: list[str] | None = None
        self.waiting = bool(frames)  # for the chain between the two frames
        self.max_diff = self.avg_diff = 0.0
        self.rounds = 0
        if not frames:
            print("Gathering data on all frames for 10 seconds...", flush=True)
        self.create_timer(0.5, self.round)
        self.round()

    def round(self) -> None:
        if self.waiting:
            self.wait_for_chain()
            return
        self.rounds += 1
        if self.chain is not None:
            try:
                latest = self.buffer.lookup_transform_core(*self.frames, Time())
            except TransformException:
                pass  # gone meanwhile: this round has no delay to add
            else:
                stamp = latest.header.stamp
                diff = self.monitor.now() - (stamp.sec + stamp.nanosec * 1e-9)
                lowpass = 0.01
                self.avg_diff = lowpass * diff + (1 - lowpass) * self.avg_diff
                self.max_diff = max(self.max_diff, diff)
        if self.rounds < REPORT_EVERY:
            return
        self.rounds = 0
        if self.chain is not None:
            print(f"\n\n\nRESULTS: for {self.frames[0]} to {self.frames[1]}")
            print(f"Chain is: {' -> '.join(self.chain)}")
            print(f"Net delay     avg = {self.avg_diff:g}: max = {self.max_diff:g}")
        else:
            print("\n\n\nRESULTS: for all Frames")
        print(self.monitor.report(self.chain), flush=True)

    def wait_for_chain(self) -> None:
        framea, frameb = self.frames
        possible, reason = self.buffer.can_transform_core(framea, frameb, Time())
        if not possible:
            self.get_logger().info(
                f"Waiting for transform {framea} ->  {frameb}: {reason}",
                throttle_duration_sec=1.0,
            )
            return
        try:
            self.chain = self.buffer._chain(frameb, Time(), framea, Time(), frameb)
        except TransformException as error:
            self.get_logger().warning(f"Transform Exception {error}")
            raise SystemExit(0) from None  # the C++ tool's return 0
        self.waiting = False
        print(f"Gathering data on {framea} -> {frameb} for 10 seconds...", flush=True)


@program_main
def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    args = user_args(argv)
    if len(args) not in (0, 2):  # the C++ tool says so with its node's logger
        get_logger("tf2_monitor_main").info("TF_Monitor: usage: tf2_monitor framea frameb")
        return 255
    return run_node(lambda: TransformMonitor(args), argv)


if __name__ == "__main__":
    sys.exit(main())
