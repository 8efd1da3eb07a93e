"""`ros2 run tf2_ros static_transform_publisher`: latch one static transform on /tf_static.

Both argument styles of ROS 2 Jazzy's tool:
    static_transform_publisher --x 1 --y 2 --yaw 0.5 --frame-id world --child-frame-id a
    static_transform_publisher x y z yaw pitch roll frame_id child_frame_id      (deprecated)
    static_transform_publisher x y z qx qy qz qw frame_id child_frame_id         (deprecated)
The old style warns "Old-style arguments are deprecated; see --help for new-style arguments".
A bad command line prints tf2's "error parsing command line arguments: ..." line (stderr) and
the usage (stdout), status 1, as the C++ program does. The node is named
static_transform_publisher_ and 16 random letters and digits, as upstream names it; its
parameters (translation.x ..., rotation.w, frame_id, child_frame_id) are read-only.
"""

from __future__ import annotations

import random
import re
import string
import sys
from collections.abc import Sequence

from geometry_msgs.msg import TransformStamped
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node

from ros_tutorials_common.quaternion import quaternion_from_rpy
from ros_tutorials_common.ros import run_node, user_args
from ros_tutorials_common.ros.node_main import UNNAMED_LOGGER
from ros_tutorials_common.shutdown import program_main
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster

USAGE = """\
usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] [--qz QZ] \
[--qw QW] [--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID --child-frame-id \
CHILD_FRAME_ID

A command line utility for manually sending a static transform.

If no translation or orientation is provided, the identity transform will be published.

The translation offsets are in meters.

The rotation may be provided with roll, pitch, yaw euler angles in radians, or as a quaternion.

required arguments:
  --frame-id FRAME_ID parent frame
  --child-frame-id CHILD_FRAME_ID child frame id

optional arguments:
  --x X                 x component of translation
  --y Y                 y component of translation
  --z Z                 z component of translation
  --qx QX               x component of quaternion rotation
  --qy QY               y component of quaternion rotation
  --qz QZ               z component of quaternion rotation
  --qw QW               w component of quaternion rotation
  --roll ROLL           roll component Euler rotation
  --pitch PITCH         pitch component Euler rotation
  --yaw YAW             yaw component Euler rotation"""

TRANSLATION = {"--x": 0, "--y": 1, "--z": 2}
QUATERNION = {"--qx": 0, "--qy": 1, "--qz": 2, "--qw": 3}
EULER = {"--roll": 0, "--pitch": 1, "--yaw": 2}
FRAMES = ("--frame-id", "--child-frame-id")
# What C++'s std::stod accepts at the start of a string (it ignores what follows).
NUMBER = re.compile(
    r"\s*[+-]?(?:inf(?:inity)?|nan|0x[0-9a-f]+|(?:\d+\.?\d*|\.\d+)(?:e[+-]?\d+)?)", re.IGNORECASE
)


class ArgumentError(Exception):
    """A command line the C++ program refuses; str() is its reason."""


class SameFrames(Exception):
    """frame_id and child_frame_id are one frame (after the parameters' overrides)."""


def _number(option: str, text: str) -> float:
    match = NUMBER.match(text)
    if match is None:
        raise ArgumentError(f"Failed to parse {option} argument as float")
    found = match.group().strip()
    return float(int(found, 16)) if "x" in found.lower() and "n" not in found else float(found)


def parse(args: Sequence[str]) -> tuple[bool, TransformStamped]:
    """(--help given, the transform) from the arguments after the program's name."""
    transform = TransformStamped()
    translation = [0.0, 0.0, 0.0]
    quaternion = [0.0, 0.0, 0.0, 1.0]
    euler = [0.0, 0.0, 0.0]
    frames = ["", ""]
    saw = {"frame": False, "quaternion": False, "euler": False, "translation": False}
    positional: list[str] = []
    wants_help = False
    index = 0
    while index < len(args):
        option = args[index]
        if option in ("-h", "--help"):
            wants_help = True
        elif option in (*TRANSLATION, *QUATERNION, *EULER, *FRAMES):
            if index == len(args) - 1:
                raise ArgumentError(f"Not enough arguments for {option}")
            index += 1
            value = args[index]
            if option in FRAMES:
                frames[FRAMES.index(option)] = value
                saw["frame"] = True
            elif option in TRANSLATION:
                translation[TRANSLATION[option]] = _number(option, value)
                saw["translation"] = True
            elif option in QUATERNION:
                quaternion[QUATERNION[option]] = _number(option, value)
                saw["quaternion"] = True
            else:
                euler[EULER[option]] = _number(option, value)
                saw["euler"] = True
        else:
            positional.append(option)
        index += 1
    if not wants_help:
        if saw["euler"] and saw["quaternion"]:
            raise ArgumentError("Cannot specify both quaternion and Euler rotations")
        if saw["euler"]:
            quaternion = list(quaternion_from_rpy(*euler))
        if len(positional) in (8, 9):
            UNNAMED_LOGGER.warning(
                "Old-style arguments are deprecated; see --help for new-style arguments"
            )
            if saw["frame"] or saw["translation"] or saw["quaternion"]:
                raise ArgumentError(
                    "Cannot specify both new-style (flags) and old-style (arguments)"
                )
            translation = [
                _number(name, text) for name, text in zip("xyz", positional[:3], strict=True)
            ]
            if len(positional) == 8:
                yaw, pitch, roll = (
                    _number(name, text)
                    for name, text in zip(("yaw", "pitch", "roll"), positional[3:6], strict=True)
                )
                quaternion = list(quaternion_from_rpy(roll, pitch, yaw))
            else:
                names = ("qx", "qy", "qz", "qw")
                quaternion = [
                    _number(name, text) for name, text in zip(names, positional[3:7], strict=True)
                ]
            frames = positional[-2:]
        elif positional:
            raise ArgumentError("Extra unparsed arguments on command-line")
        if not frames[0]:
            raise ArgumentError("Frame id must not be empty")
        if not frames[1]:
            raise ArgumentError("Child frame id must not be empty")
    transform.header.frame_id, transform.child_frame_id = frames
    t, r = transform.transform.translation, transform.transform.rotation
    t.x, t.y, t.z = translation
    r.x, r.y, r.z, r.w = quaternion
    return wants_help, transform


def node_name() -> str:
    letters = string.digits + string.ascii_lowercase + string.ascii_uppercase
    return "static_transform_publisher_" + "".join(random.choices(letters, k=16))


class StaticTransformPublisher(Node):
    """Declares the transform as read-only parameters (what a launch file may override) and
    sends it once, latched."""

    def __init__(self, transform: TransformStamped) -> None:
        t, r = transform.transform.translation, transform.transform.rotation
        super().__init__(node_name())
        read_only = ParameterDescriptor(read_only=True)
        values = {
            "translation.x": t.x, "translation.y": t.y, "translation.z": t.z,
            "rotation.x": r.x, "rotation.y": r.y, "rotation.z": r.z, "rotation.w": r.w,
            "frame_id": transform.header.frame_id, "child_frame_id": transform.child_frame_id,
        }  # fmt: skip
        for name, value in values.items():
            values[name] = self.declare_parameter(name, value, read_only).value
        t.x, t.y, t.z = values["translation.x"], values["translation.y"], values["translation.z"]
        r.x, r.y, r.z, r.w = (values[f"rotation.{axis}"] for axis in "xyzw")
        transform.header.frame_id = values["frame_id"]
        transform.child_frame_id = values["child_frame_id"]
        transform.header.stamp = self.get_clock().now().to_msg()
        self.transform = transform
        if transform.header.frame_id == transform.child_frame_id:
            self.get_logger().error(
                f"cannot publish static transform from '{transform.header.frame_id}' to "
                f"'{transform.child_frame_id}', exiting"
            )
            raise SameFrames("child_frame_id cannot equal frame_id")
        self.broadcaster = StaticTransformBroadcaster(self)
        self.broadcaster.sendTransform(transform)
        t, r = transform.transform.translation, transform.transform.rotation
        self.get_logger().info(
            "Spinning until stopped - publishing transform\n"
            f"translation: ('{t.x:f}', '{t.y:f}', '{t.z:f}')\n"
            f"rotation: ('{r.x:f}', '{r.y:f}', '{r.z:f}', '{r.w:f}')\n"
            f"from '{transform.header.frame_id}' to '{transform.child_frame_id}'"
        )


@program_main
def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    try:
        wants_help, transform = parse(user_args(argv))
    except ArgumentError as error:
        UNNAMED_LOGGER.error(f"error parsing command line arguments: {error}")
        print(USAGE)
        return 1
    if wants_help:
        print(USAGE)
        return 0
    try:
        return run_node(lambda: StaticTransformPublisher(transform), argv)
    except SameFrames:
        return 1


if __name__ == "__main__":
    sys.exit(main())
