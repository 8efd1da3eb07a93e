"""`ros2 run joint_state_publisher joint_state_publisher [URDF_FILE]`: the robot's joints on
/joint_states.

As ROS 2 Jazzy's node (ros/joint_state_publisher): the robot comes from URDF_FILE, else from
the ``robot_description`` topic (transient local, as robot_state_publisher publishes it; a
new description replaces the robot). Every ``rate`` Hz (10) it publishes a JointState naming
each movable joint (revolute, continuous, prismatic) in the file's order, with positions
(``publish_default_positions``), velocities and efforts (``publish_default_velocities``,
``publish_default_efforts``). A joint starts at ``zeros.JOINT`` if given, else at 0, or
mid-range when 0 is outside its limits; continuous joints range over -pi..pi. ``<mimic>`` tags
(``use_mimic_tags``) and ``dependent_joints.JOINT.parent/factor/offset`` make a joint follow
another; ``<safety_controller>`` soft limits narrow the range (``use_smallest_joint_limits``);
``source_list`` names JointState topics whose values it takes; ``delta`` moves every joint that
much each round, back and forth between its limits.

Only URDF is read (upstream also reads SDF and COLLADA). A malformed description is one line.
"""

from __future__ import annotations

import contextlib
import math
import sys
from collections.abc import Callable, Sequence
from typing import Any

from rcl_interfaces.msg import ParameterDescriptor, ParameterType
from rclpy.exceptions import ParameterAlreadyDeclaredException
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from sensor_msgs.msg import JointState
from std_msgs.msg import String

from ros_tutorials_common import bounded, urdf
from ros_tutorials_common.ros.node_main import run_node, user_args
from ros_tutorials_common.shutdown import program_main

NAME = "joint_state_publisher"
PARAMETERS = {  # name: (default, type), as upstream declares them
    "publish_default_efforts": (False, ParameterType.PARAMETER_BOOL),
    "publish_default_positions": (True, ParameterType.PARAMETER_BOOL),
    "publish_default_velocities": (False, ParameterType.PARAMETER_BOOL),
    "rate": (10, ParameterType.PARAMETER_INTEGER),
    "source_list": ([], ParameterType.PARAMETER_STRING_ARRAY),
    "use_mimic_tags": (True, ParameterType.PARAMETER_BOOL),
    "use_smallest_joint_limits": (True, ParameterType.PARAMETER_BOOL),
    "delta": (0.0, ParameterType.PARAMETER_DOUBLE),
}
DEPENDENT_KEYS = ("parent", "factor", "offset")


class StartError(Exception):
    """The node cannot start; its FATAL line has been logged."""


class JointStatePublisher(Node):
    def __init__(
        self, description_file: str | None = None, node_name: str = NAME, **node_options: Any
    ) -> None:
        super().__init__(
            node_name, automatically_declare_parameters_from_overrides=True, **node_options
        )
        for name, (default, kind) in PARAMETERS.items():
            # given on the command line: declared already, from the override
            with contextlib.suppress(ParameterAlreadyDeclaredException):
                self.declare_parameter(name, default, ParameterDescriptor(type=kind))
        self.free_joints: dict[str, dict[str, float | bool]] = {}
        self.joint_list: list[str] = []  # the file's order
        try:
            self.dependent_joints = self.parse_dependent_joints()
        except ValueError as error:
            self._fatal(str(error))
        self.use_mimic = self.get_parameter("use_mimic_tags").value
        self.use_small = self.get_parameter("use_smallest_joint_limits").value
        self.zeros = {k: v.value for k, v in self.get_parameters_by_prefix("zeros").items()}
        self.pub_def_positions = self.get_parameter("publish_default_positions").value
        self.pub_def_vels = self.get_parameter("publish_default_velocities").value
        self.pub_def_efforts = self.get_parameter("publish_default_efforts").value
        self.robot_description_update_cb: Callable[[], None] | None = None
        self.source_update_cb: Callable[[], None] | None = None

        if description_file is not None:
            try:
                self.configure_robot(bounded.read_text(description_file, urdf.MAX_URDF_BYTES))
            except (bounded.InputError, urdf.UrdfError) as error:
                self._fatal(f"{description_file}: {error}")
        else:
            self.get_logger().info(
                "Waiting for robot_description to be published on the robot_description topic..."
            )
        self.create_subscription(
            String,
            "robot_description",
            self.robot_description_cb,
            QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL),
        )
        self.delta = self.get_parameter("delta").value
        self.sources = [
            self.create_subscription(JointState, topic, self.source_cb, 10)
            for topic in self.get_parameter("source_list").value
        ]
        self.pub = self.create_publisher(JointState, "joint_states", 10)
        rate = self.get_parameter("rate").value
        if not isinstance(rate, int) or rate <= 0:
            self._fatal(f"rate must be a positive integer, not {rate!r}")
        self.timer = self.create_timer(1.0 / rate, self.timer_callback)

    def _fatal(self, reason: str) -> None:
        self.get_logger().fatal(reason)
        raise StartError(reason)

    def parse_dependent_joints(self) -> dict[str, dict]:
        """``dependent_joints.JOINT.KEY`` parameters as {JOINT: {KEY: value}}."""
        found: dict[str, dict] = {}
        for name, parameter in self.get_parameters_by_prefix("dependent_joints").items():
            joint, _, key = name.partition(".")
            if not key or "." in key:
                raise ValueError(f"Invalid dependent_joint name '{name}'")
            if key not in DEPENDENT_KEYS:
                allowed = ", ".join(f"'{k}'" for k in DEPENDENT_KEYS)
                raise ValueError(
                    f"Invalid dependent_joint name '{key}' (allowed values are {allowed})"
                )
            found.setdefault(joint, {})[key] = parameter.value
        if any("parent" not in entry for entry in found.values()):
            raise ValueError("All dependent_joints must at least have a parent")
        return found

    def _init_joint(self, minval: float, maxval: float, zeroval: float) -> dict:
        joint: dict[str, float | bool] = {"min": minval, "max": maxval, "zero": zeroval}
        if self.pub_def_positions:
            joint["position"] = zeroval
        if self.pub_def_vels:
            joint["velocity"] = 0.0
        if self.pub_def_efforts:
            joint["effort"] = 0.0
        return joint

    def configure_robot(self, description: str) -> None:
        """Take the movable joints of a URDF text (UrdfError if it is not a valid one)."""
        robot = urdf.parse(description)
        free_joints: dict[str, dict] = {}
        joint_list: list[str] = []
        dependent = {k: v for k, v in self.dependent_joints.items()}
        for joint in robot.moving_joints():
            if joint.type == "continuous":
                minval, maxval = -math.pi, math.pi
            else:
                minval, maxval = joint.lower, joint.upper
            if self.use_small:
                if joint.soft_lower is not None:
                    minval = max(minval, joint.soft_lower)
                if joint.soft_upper is not None:
                    maxval = min(maxval, joint.soft_upper)
            joint_list.append(joint.name)
            if self.use_mimic and joint.mimic is not None:
                dependent[joint.name] = {
                    "parent": joint.mimic.joint,
                    "factor": joint.mimic.multiplier,
                    "offset": joint.mimic.offset,
                }
                continue
            if joint.name in dependent:
                continue
            if joint.name in self.zeros:
                zeroval = self.zeros[joint.name]
            elif minval > 0 or maxval < 0:
                zeroval = (maxval + minval) / 2
            else:
                zeroval = 0.0
            entry = self._init_joint(minval, maxval, zeroval)
            if joint.type == "continuous":
                entry["continuous"] = True
            free_joints[joint.name] = entry
        for name, entry in dependent.items():
            if name in joint_list and entry["parent"] not in free_joints | dependent:
                raise urdf.UrdfError(f"joint [{name}] follows [{entry['parent']}], not movable")
        self.free_joints, self.joint_list, self.dependent_joints = (
            free_joints,
            joint_list,
            dependent,
        )
        if self.robot_description_update_cb is not None:
            self.robot_description_update_cb()

    def robot_description_cb(self, msg: String) -> None:
        try:
            self.configure_robot(msg.data)
        except urdf.UrdfError as error:
            self.get_logger().warning(f"robot_description: {error}")

    def source_cb(self, msg: JointState) -> None:
        for i, name in enumerate(msg.name):
            joint = self.free_joints.get(name)
            if joint is None:
                continue
            for key, values in (
                ("position", msg.position),
                ("velocity", msg.velocity),
                ("effort", msg.effort),
            ):
                if i < len(values):
                    joint[key] = values[i]
        if self.source_update_cb is not None:
            self.source_update_cb()

    def set_source_update_cb(self, user_cb: Callable[[], None]) -> None:
        self.source_update_cb = user_cb

    def set_robot_description_update_cb(self, user_cb: Callable[[], None]) -> None:
        self.robot_description_update_cb = user_cb

    def _follow(self, name: str) -> tuple[str, float, float] | None:
        """The free joint a dependent joint follows, with the chain's factor and offset."""
        entry = self.dependent_joints[name]
        parent = entry["parent"]
        factor, offset = entry.get("factor", 1.0), entry.get("offset", 0.0)
        chain = [name]
        while parent in self.dependent_joints:
            if parent in chain:
                self.get_logger().error(
                    f"Found an infinite recursive mimic chain: {[*chain, parent]}"
                )
                return None
            chain.append(parent)
            entry = self.dependent_joints[parent]
            parent = entry["parent"]
            offset += factor * entry.get("offset", 0.0)
            factor *= entry.get("factor", 1.0)
        return (parent, factor, offset) if parent in self.free_joints else None

    def timer_callback(self) -> None:
        msg = JointState()
        msg.header.stamp = self.get_clock().now().to_msg()
        if self.delta > 0:
            self.update(self.delta)
        joints = list(self.free_joints.values())
        has_position = bool(self.dependent_joints) or any("position" in j for j in joints)
        has_velocity = any("velocity" in j for j in joints)
        has_effort = any("effort" in j for j in joints)
        positions, velocities, efforts = [], [], []
        for name in self.joint_list:
            if name in self.free_joints:
                joint, factor, offset = self.free_joints[name], 1.0, 0.0
            elif name in self.dependent_joints:
                followed = self._follow(name)
                if followed is None:
                    continue
                joint, factor, offset = self.free_joints[followed[0]], followed[1], followed[2]
            else:
                continue
            msg.name.append(name)
            positions.append(float(joint.get("position", 0.0)) * factor + offset)
            velocities.append(float(joint.get("velocity", 0.0)) * factor)
            efforts.append(float(joint.get("effort", 0.0)))
        msg.position = positions if has_position else []
        msg.velocity = velocities if has_velocity else []
        msg.effort = efforts if has_effort else []
        if msg.name:
            self.pub.publish(msg)

    def update(self, delta: float) -> None:
        for joint in self.free_joints.values():
            if "position" not in joint:
                continue
            if joint.get("forward", True):
                joint["position"] += delta
                if joint["position"] > joint["max"]:
                    if joint.get("continuous", False):
                        joint["position"] = joint["min"]
                    else:
                        joint["position"] = joint["max"]
                        joint["forward"] = False
            else:
                joint["position"] -= delta
                if joint["position"] < joint["min"]:
                    joint["position"] = joint["min"]
                    joint["forward"] = True


@program_main
def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    args = user_args(argv)
    if len(args) > 1:
        print(
            "usage: joint_state_publisher [-h] [description_file]\n"
            f"joint_state_publisher: error: unrecognized arguments: {' '.join(args[1:])}",
            file=sys.stderr,
        )
        return 2
    try:
        return run_node(lambda: JointStatePublisher(args[0] if args else None), argv)
    except StartError:
        return 1


if __name__ == "__main__":
    sys.exit(main())
