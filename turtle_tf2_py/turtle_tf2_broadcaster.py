"""turtle_tf2_broadcaster: broadcast a turtle's pose as the transform world -> TURTLENAME.

ros2 run turtle_tf2_py turtle_tf2_broadcaster --ros-args -p turtlename:=turtle1
"""

import math

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from turtlesim.msg import Pose

from tf2_ros import TransformBroadcaster


class FramePublisher(Node):
    def __init__(self):
        super().__init__("turtle_tf2_frame_publisher")
        # Which turtle: its pose topic and its frame's name
        self.turtlename = self.declare_parameter("turtlename", "turtle").value
        self.tf_broadcaster = TransformBroadcaster(self)
        self.subscription = self.create_subscription(
            Pose, f"/{self.turtlename}/pose", self.handle_turtle_pose, 1
        )

    def handle_turtle_pose(self, msg):
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = "world"
        t.child_frame_id = self.turtlename
        # A turtle lives in the plane: z stays 0 and it turns about z only
        t.transform.translation.x = msg.x
        t.transform.translation.y = msg.y
        t.transform.translation.z = 0.0
        t.transform.rotation.z = math.sin(msg.theta / 2)
        t.transform.rotation.w = math.cos(msg.theta / 2)
        self.tf_broadcaster.sendTransform(t)


def main() -> None:
    rclpy.init()
    node = FramePublisher()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
