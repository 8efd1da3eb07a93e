"""`ros2 run robot_state_publisher robot_state_publisher`: a robot's links as tf2 frames.

As ROS 2 Jazzy's node (ros/robot_state_publisher): the URDF comes in the parameter
``robot_description`` (required; a URDF file named as the first argument is the old fallback,
with a warning), and is republished on ``/robot_description`` (std_msgs/String, transient
local, so a later 3D view or joint_state_publisher still gets it). The fixed joints' transforms
go once on ``/tf_static``; each ``/joint_states`` message (sensor data QoS) turns into the
moving joints' transforms on ``/tf``, stamped with the message's stamp, at most
``publish_frequency`` times a second per joint unless ``ignore_timestamp`` is true; mimic
joints follow the joint they mimic. ``frame_prefix`` is put before every frame name. Setting
``robot_description`` while it runs replaces the robot (a malformed one is refused).

A malformed URDF is one line (FATAL at start, the refusal's reason when set later); the URDF is
read bounded (ros_tutorials_common/urdf.py).
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from geometry_msgs.msg import TransformStamped
from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from rclpy.time import Time
from sensor_msgs.msg import JointState
from std_msgs.msg import String

from ros_tutorials_common import bounded, urdf
from ros_tutorials_common.ros.node_main import run_node, user_args
from ros_tutorials_common.shutdown import program_main
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster
from tf2_ros.transform_broadcaster import TransformBroadcaster

NAME = "robot_state_publisher"
MAX_FREQUENCY = 1000.0


class StartError(Exception):
    """The node cannot start; its FATAL line has been logged."""


class RobotStatePublisher(Node):
    def __init__(self, description_file: str | None = None) -> None:
        super().__init__(NAME)
        description = self.declare_parameter(
            "robot_description",
            "",
            ParameterDescriptor(
                description="The original description of the robot in URDF form",
                dynamic_typing=True,  # a wrong type is refused below in one line
            ),
        ).value
        if not isinstance(description, str):
            self._fatal("robot_description must be a string (the URDF text)")
        if not description:
            if description_file is None:
                self._fatal("robot_description parameter must not be empty")
            self.get_logger().warning(
                "No robot_description parameter, but command-line argument available.  Assuming "
                "argument is name of URDF file.  This backwards compatibility fallback will be "
                "removed in the future."
            )
            try:
                description = bounded.read_text(description_file, urdf.MAX_URDF_BYTES)
            except bounded.InputError as error:
                self._fatal(f"Failed to open URDF file: {error}")
            self.set_parameters([Parameter("robot_description", value=description)])
        self.publish_frequency = self.declare_parameter("publish_frequency", 20.0).value
        if not 0.0 <= self.publish_frequency <= MAX_FREQUENCY:
            self._fatal("publish_frequency must be between 0 and 1000")
        self.declare_parameter("frame_prefix", "")
        self.declare_parameter("ignore_timestamp", False)

        self.tf_broadcaster = TransformBroadcaster(self)
        self.static_tf_broadcaster = StaticTransformBroadcaster(self)
        self.description_pub = self.create_publisher(
            String,
            "robot_description",
            QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL),
        )
        try:
            self.setup_urdf(description)
        except urdf.UrdfError as error:
            self._fatal(f"Unable to initialize urdf::model from robot description: {error}")
        self.joint_state_sub = self.create_subscription(
            JointState, "joint_states", self.callback_joint_state, qos_profile_sensor_data
        )
        self.publish_fixed_transforms()
        self.add_on_set_parameters_callback(self.parameter_update)
        self.add_post_set_parameters_callback(self.parameters_set)

    def _fatal(self, reason: str) -> None:
        self.get_logger().fatal(reason)
        raise StartError(reason)

    def setup_urdf(self, description: str) -> None:
        """Read the robot (UrdfError if it is no valid one), then announce its description."""
        self.robot = urdf.parse(description)
        self.moving = {j.name: j for j in self.robot.joints.values() if j.type in urdf.MOVING}
        # floating joints are not supported (as upstream: skipped); planar ones stay fixed
        self.fixed = [
            j for j in self.robot.joints.values() if j.type not in (*urdf.MOVING, "floating")
        ]
        self.last_publish_time: dict[str, int] = {}
        self.last_callback_time = 0
        self.description_pub.publish(String(data=description))
        self.get_logger().info("Robot initialized")

    def transform(self, joint: urdf.Joint, position: float, stamp) -> TransformStamped:
        prefix = self.get_parameter("frame_prefix").value
        pose = joint.pose(position)
        t = TransformStamped()
        t.header.stamp = stamp
        t.header.frame_id = prefix + joint.parent
        t.child_frame_id = prefix + joint.child
        t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = pose.xyz
        r = t.transform.rotation
        r.x, r.y, r.z, r.w = pose.rotation
        return t

    def publish_fixed_transforms(self) -> None:
        stamp = self.get_clock().now().to_msg()
        self.static_tf_broadcaster.sendTransform(
            [self.transform(joint, 0.0, stamp) for joint in self.fixed]
        )

    def callback_joint_state(self, state: JointState) -> None:
        if len(state.name) != len(state.position):
            if not state.position and state.name:
                self.get_logger().warning(
                    "Robot state publisher ignored a JointState message about joint(s) "
                    f'"{state.name[0]}"(,...) whose position member was empty.'
                )
            else:
                self.get_logger().error(
                    "Robot state publisher ignored an invalid JointState message"
                )
            return
        now = self.get_clock().now().nanoseconds
        if self.last_callback_time > now:  # time went backwards (a bag played again)
            self.get_logger().warning("Moved backwards in time, re-publishing joint transforms!")
            self.last_publish_time.clear()
        self.last_callback_time = now
        last_published = min([now, *(self.last_publish_time.get(name, 0) for name in state.name)])
        stamp = Time.from_msg(state.header.stamp).nanoseconds
        frequency = self.get_parameter("publish_frequency").value
        interval = int(1e9 / frequency) if frequency > 0 else 0
        if not self.get_parameter("ignore_timestamp").value and stamp < last_published + interval:
            return
        positions = dict(zip(state.name, state.position, strict=True))
        for joint in self.moving.values():
            mimic = joint.mimic
            if mimic is not None and mimic.joint in positions and joint.name not in positions:
                positions[joint.name] = positions[mimic.joint] * mimic.multiplier + mimic.offset
        transforms = [
            self.transform(self.moving[name], position, state.header.stamp)
            for name, position in positions.items()
            if name in self.moving
        ]
        self.tf_broadcaster.sendTransform(transforms)
        for name in state.name:
            self.last_publish_time[name] = stamp

    def parameter_update(self, parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            if parameter.name == "robot_description":
                if not isinstance(parameter.value, str) or not parameter.value:
                    return SetParametersResult(successful=False, reason="Empty URDF is not allowed")
                try:
                    urdf.parse(parameter.value)
                except urdf.UrdfError as error:
                    reason = f"Unable to initialize urdf::model from robot description: {error}"
                    self.get_logger().warning(reason)
                    return SetParametersResult(successful=False, reason=reason)
            elif parameter.name == "publish_frequency" and not (
                isinstance(parameter.value, float) and 0.0 <= parameter.value <= MAX_FREQUENCY
            ):
                return SetParametersResult(
                    successful=False, reason="publish_frequency must be between 0.0 and 1000.0"
                )
        return SetParametersResult(successful=True)

    def parameters_set(self, parameters: list[Parameter]) -> None:
        for parameter in parameters:
            if parameter.name == "robot_description":
                self.setup_urdf(parameter.value)
                self.publish_fixed_transforms()


@program_main
def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    args = user_args(argv)
    try:
        return run_node(lambda: RobotStatePublisher(args[0] if args else None), argv)
    except StartError:
        return 1


if __name__ == "__main__":
    sys.exit(main())
