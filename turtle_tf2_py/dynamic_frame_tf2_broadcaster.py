"""dynamic_frame_tf2_broadcaster: the frame carrot1 circling turtle1 at 10 m, moved each second.

ros2 run turtle_tf2_py dynamic_frame_tf2_broadcaster
"""

import math

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

from tf2_ros import TransformBroadcaster


class DynamicFrameBroadcaster(Node):
    def __init__(self):
        super().__init__("dynamic_frame_tf2_broadcaster")
        self.tf_broadcaster = TransformBroadcaster(self)
        self.timer = self.create_timer(0.1, self.broadcast_timer_callback)

    def broadcast_timer_callback(self):
        now = self.get_clock().now()
        angle = now.seconds_nanoseconds()[0] * math.pi  # whole seconds: half a turn each
        t = TransformStamped()
        t.header.stamp = now.to_msg()
        t.header.frame_id = "turtle1"
        t.child_frame_id = "carrot1"
        t.transform.translation.x = 10 * math.sin(angle)
        t.transform.translation.y = 10 * math.cos(angle)
        t.transform.rotation.w = 1.0
        self.tf_broadcaster.sendTransform(t)


def main() -> None:
    rclpy.init()
    node = DynamicFrameBroadcaster()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
