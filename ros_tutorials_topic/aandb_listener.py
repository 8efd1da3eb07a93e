"""The AandB listener of seed 002: hears the AandB talker.

Subscribes to ``chatter`` (``ros_tutorials_interfaces/msg/AandB``) and logs each message as the
seed's listener.cpp does: ``I heard: msg:a 1.000000, msg:b 2.000000``. Node ``listener``.

    aandb_listener      (or: rosrun beginner_tutorials aandb_listener)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import AandB


class AandBListener(Node):
    def __init__(self) -> None:
        super().__init__("listener")
        # chatter_callback runs for every AandB message on chatter (queue of 1000).
        self.subscription = self.create_subscription(AandB, "chatter", self.chatter_callback, 1000)

    def chatter_callback(self, msg: AandB) -> None:
        self.get_logger().info(f"I heard: msg:a {msg.a:f}, msg:b {msg.b:f}")


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = AandBListener()  # create the node
    try:
        rclpy.spin(node)  # until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
