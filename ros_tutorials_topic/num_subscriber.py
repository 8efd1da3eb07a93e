"""The Num subscriber of seed 003 (package pub_sub, executable subscriber).

Subscribes to ``/publisher`` (``ros_tutorials_interfaces/msg/Num``) and logs each number as
the seed's sub.cpp does: ``I heard: [7]``. Node ``sub``.

    num_subscriber      (or: rosrun pub_sub subscriber)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import Num

from ros_tutorials_common.dds import apply_dds_defaults


class NumSubscriber(Node):
    def __init__(self) -> None:
        super().__init__("sub", enable_logger_service=True)
        self.subscription = self.create_subscription(Num, "/publisher", self.pub_callback, 1000)

    def pub_callback(self, msg: Num) -> None:
        self.get_logger().info(f"I heard: [{msg.num}]")


def main(args: list[str] | None = None) -> None:
    apply_dds_defaults()  # this project's DDS settings (localhost only), before init
    try:
        rclpy.init(args=args)
    except RuntimeError as error:  # a malformed ROS argument, e.g. --ros-args -r bad
        raise SystemExit(f"error: {str(error).split(', at ')[0]}") from None
    node = NumSubscriber()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or shutdown: a normal end
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
