"""`ros2 run tf2_ros tf2_echo SOURCE TARGET [RATE]`: print a transform, RATE times a second.

As ROS 2 Jazzy's C++ tool: it looks up TARGET's pose in SOURCE's frame (the transform that
takes data from TARGET into SOURCE) at the latest common time and prints::

    At time 1700000000.123456789
    - Translation: [0.000, 0.000, 0.000]
    - Rotation: in Quaternion [0.000, 0.000, 0.000, 1.000]
    - Rotation: in RPY (radian) [0.000, -0.000, 0.000]
    - Rotation: in RPY (degree) [0.000, -0.000, 0.000]
    - Matrix:
      1.000  0.000  0.000  0.000
    ...

Until the frames are there it logs "Waiting for transform SOURCE ->  TARGET: <tf2's reason>"
at each look (RATE times a second, at most once a second). No frames: the usage, status 1; a
RATE that is not a number: one line on stderr, status 2 (3 with junk after a number), as the
C++ tool.
"""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Sequence

from rclpy.node import Node
from rclpy.time import Time

from ros_tutorials_common.ros import run_node, user_args
from ros_tutorials_common.shutdown import program_main
from tf2_py import TransformException
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener

USAGE = """\
Usage: tf2_echo source_frame target_frame [echo_rate]

This will echo the transform from the coordinate frame of the source_frame
to the coordinate frame of the target_frame. 
Note: This is the transform to get data from target_frame into the source_frame.
Default echo rate is 1 if echo_rate is not given.
"""  # noqa: W291 - the C++ tool's line ends with a space
# What C's strtof reads at the start of a string.
FLOAT = re.compile(r"\s*[+-]?(?:inf(?:inity)?|nan|(?:\d+\.?\d*|\.\d+)(?:e[+-]?\d+)?)", re.I)


def parse_rate(text: str) -> tuple[float | None, int]:
    """(rate, 0), or (None, exit status) after the C++ tool's line on stderr."""
    match = FLOAT.match(text)
    if match is None or match.end() != len(text):
        print(
            f"Failed to convert rate argument '{text}' to a floating-point number", file=sys.stderr
        )
        return None, 2 if match is None else 3
    rate = float(match.group())
    if not (0 < rate < math.inf):  # rclcpp::Rate refuses it too, with an exception
        print(f"The echo rate '{text}' must be a number greater than 0", file=sys.stderr)
        return None, 2
    return rate, 0


def euler_ypr(m: list[list[float]]) -> tuple[float, float, float]:
    """(yaw, pitch, roll) of a rotation matrix, tf2's getEulerYPR (its first solution)."""
    if abs(m[2][0]) >= 1:
        delta = math.atan2(m[2][1], m[2][2])
        return 0.0, (math.pi / 2 if m[2][0] < 0 else -math.pi / 2), delta
    pitch = -math.asin(m[2][0])
    cos = math.cos(pitch)
    roll = math.atan2(m[2][1] / cos, m[2][2] / cos)
    yaw = math.atan2(m[1][0] / cos, m[0][0] / cos)
    return yaw, pitch, roll


def rotation_matrix(x: float, y: float, z: float, w: float) -> list[list[float]]:
    s = 2.0 / (x * x + y * y + z * z + w * w)
    return [
        [1 - s * (y * y + z * z), s * (x * y - z * w), s * (x * z + y * w)],
        [s * (x * y + z * w), 1 - s * (x * x + z * z), s * (y * z - x * w)],
        [s * (x * z - y * w), s * (y * z + x * w), 1 - s * (x * x + y * y)],
    ]


def format_transform(transform: object) -> str:
    """The lines tf2_echo prints for one TransformStamped."""
    stamp = transform.header.stamp  # type: ignore[attr-defined]
    t = transform.transform.translation  # type: ignore[attr-defined]
    r = transform.transform.rotation  # type: ignore[attr-defined]
    matrix = rotation_matrix(r.x, r.y, r.z, r.w)
    yaw, pitch, roll = euler_ypr(matrix)
    degrees = [math.degrees(angle) for angle in (roll, pitch, yaw)]
    rows = [
        "".join(f" {value:6.3f}" for value in (*matrix[i], (t.x, t.y, t.z)[i])) for i in range(3)
    ]
    rows.append("".join(f" {value:6.3f}" for value in (0.0, 0.0, 0.0, 1.0)))
    return "\n".join(
        [
            # The C++ tool prints the nanoseconds as a plain number, without leading zeros.
            f"At time {stamp.sec}.{stamp.nanosec}",
            f"- Translation: [{t.x:.3f}, {t.y:.3f}, {t.z:.3f}]",
            f"- Rotation: in Quaternion [{r.x:.3f}, {r.y:.3f}, {r.z:.3f}, {r.w:.3f}]",
            f"- Rotation: in RPY (radian) [{roll:.3f}, {pitch:.3f}, {yaw:.3f}]",
            f"- Rotation: in RPY (degree) [{degrees[0]:.3f}, {degrees[1]:.3f}, {degrees[2]:.3f}]",
            "- Matrix:",
            *rows,
        ]
    )


class TransformEcho(Node):
    """tf2_echo's node, spun by ``run_node``: the C++ tool's loop (wait for the frames, then
    echo, a rate.sleep() after each look) as a timer at the echo rate, the first look at once."""

    def __init__(self, source: str, target: str, period: float) -> None:
        super().__init__("tf2_echo")
        self.source, self.target = source, target
        self.buffer = Buffer()
        self.listener = TransformListener(self.buffer, self)  # its subscriptions: this spin
        self.found = False  # the frames were there once: from then on, echo
        self.printed = False
        self.create_timer(period, self.look)
        self.look()

    def look(self) -> None:
        if not self.found:
            possible, reason = self.buffer.can_transform_core(self.source, self.target, Time())
            if not possible:
                self.get_logger().info(
                    f"Waiting for transform {self.source} ->  {self.target}: {reason}",
                    throttle_duration_sec=1.0,
                )
                return
            self.found = True
        try:
            print(
                format_transform(
                    self.buffer.lookup_transform_core(self.source, self.target, Time())
                )
            )
            self.printed = True
        except TransformException as error:
            now = self.get_clock().now().nanoseconds / 1e9
            print(f"Failure at {now:.3f}" if self.printed else f"Failure at {now:g}")
            print(f"Exception thrown:{error}")
            print("The current list of frames is:")
            print(self.buffer.all_frames_as_string())
        sys.stdout.flush()


@program_main  # `tf2_echo a b | head`
def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    args = user_args(argv)
    if len(args) not in (2, 3):
        print(USAGE)
        return 1
    rate = 1.0
    if len(args) == 3:
        parsed, status = parse_rate(args[2])
        if parsed is None:
            return status
        rate = parsed
    period = min(1.0 / rate, 86400.0)  # rclpy's timer refuses a period of 1e300 s
    return run_node(lambda: TransformEcho(args[0], args[1], period), argv)


if __name__ == "__main__":
    sys.exit(main())
