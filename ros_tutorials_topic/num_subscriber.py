"""The Num subscriber of seed 003 (package pub_sub, executable subscriber).

Subscribes to ``/publisher`` (``ros_tutorials_interfaces/msg/Num``) and logs each number as
the seed's sub.cpp does: ``I heard: [7]``. Node ``sub``.

    num_subscriber      (or: rosrun pub_sub subscriber)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import Num


class NumSubscriber(Node):
    def __init__(self) -> None:
        super().__init__("sub")
        self.subscription = self.create_subscription(Num, "/publisher", self.pub_callback, 1000)

    def pub_callback(self, msg: Num) -> None:
        self.get_logger().info(f"I heard: [{msg.num}]")


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = NumSubscriber()  # create the node
    try:
        rclpy.spin(node)  # until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
