"""mimic: make one turtle copy another's motion (seed 003's launch file joins two simulators).

    mimic --ros-args -r input:=/turtlesim1/turtle1 -r output:=/turtlesim2/turtle1

Node ``turtle_mimic`` subscribes ``input/pose`` (turtlesim/msg/Pose) and publishes, for each
pose, a geometry_msgs/msg/Twist on ``output/cmd_vel`` with the pose's linear and angular
velocity: the second turtle drives as the first one does.

Both ways of remapping work: ROS 2's, one topic at a time (``-r /input/pose:=/t1/turtle1/pose``),
and ROS 1's, the namespace (``-r input:=t1/turtle1``, as seed 003's launch file does): ROS 1's
mimic used a node handle in namespace ``input``, and remapping that namespace moved its topics.
rcl remaps whole names only, so the namespaces are resolved here first.
"""

from __future__ import annotations

import sys

from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from turtlesim.msg import Pose

from ros_tutorials_common.ros import run_node
from ros_tutorials_common.shutdown import program_main


class Mimic(Node):
    def __init__(self, **kwargs) -> None:
        super().__init__("turtle_mimic", enable_logger_service=True, **kwargs)
        qos = QoSProfile(depth=7, reliability=ReliabilityPolicy.RELIABLE)  # turtlesim's
        # "/input" unless a ROS 1-style namespace remap moved it (see the docstring)
        input_ns, output_ns = self.resolve_topic_name("input"), self.resolve_topic_name("output")
        self.publisher = self.create_publisher(Twist, f"{output_ns}/cmd_vel", qos)
        self.subscription = self.create_subscription(Pose, f"{input_ns}/pose", self.on_pose, qos)

    def on_pose(self, pose: Pose) -> None:
        twist = Twist()
        twist.linear.x = pose.linear_velocity
        twist.angular.z = pose.angular_velocity
        self.publisher.publish(twist)


@program_main
def main(argv: list[str] | None = None) -> int:
    return run_node(Mimic, argv)  # rclpy.init with the DDS defaults, spin until Ctrl-C


if __name__ == "__main__":
    sys.exit(main())
