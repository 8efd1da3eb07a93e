"""The Num subscriber of seed 003 (package pub_sub, executable subscriber).

Subscribes to ``/publisher`` (``ros_tutorials_interfaces/msg/Num``) and logs each number as
the seed's sub.cpp does: ``I heard: [7]``. Node ``sub``.

    num_subscriber      (or: rosrun pub_sub subscriber)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import Num

from ros_tutorials_common.ros import ros_args


class NumSubscriber(Node):
    def __init__(self) -> None:
        super().__init__("sub", enable_logger_service=True)
        self.subscription = self.create_subscription(Num, "/publisher", self.pub_callback, 1000)

    def pub_callback(self, msg: Num) -> None:
        self.get_logger().info(f"I heard: [{msg.num}]")


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=ros_args(args))  # initialise ROS 2 (reads --ros-args; DDS defaults)
    node = NumSubscriber()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or shutdown: a normal end
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
