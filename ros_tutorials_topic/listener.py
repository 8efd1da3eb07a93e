"""Listener (the classic rospy/roscpp tutorial of seeds 001, 003, 004).

Subscribes to ``chatter`` (std_msgs/String) and logs "I heard: [...]" for each message.

    listener               (or: python -m ros_tutorials_topic.listener)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import String


class Listener(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("listener", **node_kwargs)
        self.subscription = self.create_subscription(String, "chatter", self.on_message, 1000)

    def on_message(self, msg: String) -> None:
        self.get_logger().info(f"I heard: [{msg.data}]")


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = Listener()  # create the node
    try:
        rclpy.spin(node)  # call on_message per message, until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
