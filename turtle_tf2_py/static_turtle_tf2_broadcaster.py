"""static_turtle_tf2_broadcaster: publish world -> CHILD once, on /tf_static (latched).

ros2 run turtle_tf2_py static_turtle_tf2_broadcaster mystaticturtle 0 0 1 0 0 0
"""

import math
import sys

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster


def quaternion_from_euler(roll, pitch, yaw):
    """(x, y, z, w) of the rotation about x by roll, then y by pitch, then z by yaw."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
        cr * cp * cy + sr * sp * sy,
    )


class StaticFramePublisher(Node):
    """Broadcast one transform that never changes, from `world` to a static turtle frame."""

    def __init__(self, transformation):
        super().__init__("static_turtle_tf2_broadcaster")
        self.tf_static_broadcaster = StaticTransformBroadcaster(self)
        self.make_transforms(transformation)

    def make_transforms(self, transformation):
        child, x, y, z, roll, pitch, yaw = transformation
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = "world"
        t.child_frame_id = child
        t.transform.translation.x = float(x)
        t.transform.translation.y = float(y)
        t.transform.translation.z = float(z)
        q = quaternion_from_euler(float(roll), float(pitch), float(yaw))
        t.transform.rotation.x, t.transform.rotation.y = q[0], q[1]
        t.transform.rotation.z, t.transform.rotation.w = q[2], q[3]
        self.tf_static_broadcaster.sendTransform(t)


def main() -> None:
    logger = rclpy.logging.get_logger("logger")
    args = rclpy.utilities.remove_ros_args(sys.argv)[1:]
    if len(args) != 7:
        logger.info(
            "Invalid number of parameters. Usage: \n"
            "$ ros2 run turtle_tf2_py static_turtle_tf2_broadcaster "
            "child_frame_name x y z roll pitch yaw"
        )
        sys.exit(1)
    if args[0] == "world":
        logger.info('Your static turtle name cannot be "world"')
        sys.exit(2)
    try:
        [float(value) for value in args[1:]]
    except ValueError as error:
        logger.error(f"x y z roll pitch yaw must be numbers: {error}")
        sys.exit(1)

    rclpy.init()
    node = StaticFramePublisher(args)
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
