"""fixed_frame_tf2_broadcaster: the frame carrot1, 2 m to turtle1's left, ten times a second.

ros2 run turtle_tf2_py fixed_frame_tf2_broadcaster
"""

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

from tf2_ros import TransformBroadcaster


class FixedFrameBroadcaster(Node):
    def __init__(self):
        super().__init__("fixed_frame_tf2_broadcaster")
        self.tf_broadcaster = TransformBroadcaster(self)
        self.timer = self.create_timer(0.1, self.broadcast_timer_callback)

    def broadcast_timer_callback(self):
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = "turtle1"
        t.child_frame_id = "carrot1"
        t.transform.translation.y = 2.0  # the rest stays 0: no rotation (w = 1)
        t.transform.rotation.w = 1.0
        self.tf_broadcaster.sendTransform(t)


def main() -> None:
    rclpy.init()
    node = FixedFrameBroadcaster()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
