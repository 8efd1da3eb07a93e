"""Talker (the classic rospy/roscpp tutorial of seeds 001, 003, 004).

Publishes std_msgs/String "hello world N" on ``chatter`` ten times a second.

    talker                 (or: python -m ros_tutorials_topic.talker)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("talker", **node_kwargs)
        self.publisher = self.create_publisher(String, "chatter", 10)  # queue_size=10
        self.timer = self.create_timer(0.1, self.publish_message)  # 10 Hz
        self.count = 0

    def publish_message(self) -> None:
        msg = String(data=f"hello world {self.count}")
        self.get_logger().info(msg.data)
        self.publisher.publish(msg)
        self.count += 1


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = Talker()  # create the node
    try:
        rclpy.spin(node)  # run its timer until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
