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
import threading
import time
from collections import deque
from collections.abc import Sequence

import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from rclpy.time import Time
from tf2_msgs.msg import TFMessage

from ros_tutorials_common.ros import init, node_stopped, user_args
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
        self.lock = threading.Lock()
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
        with self.lock:
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
        with self.lock:
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


@program_main
def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    args = user_args(argv)
    init(argv)
    node = listener = None
    try:
        node = rclpy.create_node("tf2_monitor_main")
        if len(args) not in (0, 2):
            node.get_logger().info("TF_Monitor: usage: tf2_monitor framea frameb")
            return 255
        buffer = Buffer(node=node)
        monitor = Monitor(node)
        # Its thread spins the node, the monitor's subscription too, as tf2_monitor's listener.
        listener = TransformListener(buffer, node, spin_thread=True)
        chain = None
        if args:
            framea, frameb = args
            while rclpy.ok():
                possible, reason = buffer.can_transform_core(framea, frameb, Time())
                if possible:
                    break
                node.get_logger().info(
                    f"Waiting for transform {framea} ->  {frameb}: {reason}",
                    throttle_duration_sec=1.0,
                )
                time.sleep(0.5)
            try:
                chain = buffer._chain(frameb, Time(), framea, Time(), frameb)
            except TransformException as error:
                node.get_logger().warning(f"Transform Exception {error}")
                return 0
            print(f"Gathering data on {framea} -> {frameb} for 10 seconds...", flush=True)
        else:
            print("Gathering data on all frames for 10 seconds...", flush=True)
        _report_forever(buffer, monitor, args, chain)
    except BaseException as error:
        if not node_stopped(error):  # Ctrl-C, SIGTERM: the normal end
            raise
    finally:
        if listener is not None:  # its thread must be done with the node before it goes
            listener.stop_spinning()
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0


def _report_forever(
    buffer: Buffer, monitor: Monitor, args: list[str], chain: list[str] | None
) -> None:
    max_diff = avg_diff = 0.0
    lowpass = 0.01
    rounds = 0
    while rclpy.ok():
        rounds += 1
        if chain is not None:
            try:
                latest = buffer.lookup_transform_core(args[0], args[1], Time())
            except TransformException:
                pass  # gone meanwhile: this round has no delay to add
            else:
                stamp = latest.header.stamp
                diff = monitor.now() - (stamp.sec + stamp.nanosec * 1e-9)
                avg_diff = lowpass * diff + (1 - lowpass) * avg_diff
                max_diff = max(max_diff, diff)
        time.sleep(0.5)
        if rounds < REPORT_EVERY:
            continue
        rounds = 0
        if chain is not None:
            print(f"\n\n\nRESULTS: for {args[0]} to {args[1]}")
            print(f"Chain is: {' -> '.join(chain)}")
            print(f"Net delay     avg = {avg_diff:g}: max = {max_diff:g}")
        else:
            print("\n\n\nRESULTS: for all Frames")
        print(monitor.report(chain), flush=True)


if __name__ == "__main__":
    sys.exit(main())
