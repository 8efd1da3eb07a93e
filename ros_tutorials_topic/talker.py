"""Talker (the classic roscpp/rospy tutorial of seeds 001, 003, 004).

Publishes std_msgs/String "hello world N" on ``chatter`` ten times a second.

    python -m ros_tutorials_topic.talker         (or: talker)
"""

from rclpy.node import Node
from std_msgs.msg import String

from ros_tutorials_common.node_main import run_node

QUEUE_SIZE = 10
RATE_HZ = 10.0


class Talker(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("talker", enable_logger_service=True, **node_kwargs)
        self.publisher = self.create_publisher(String, "chatter", QUEUE_SIZE)
        self.timer = self.create_timer(1.0 / RATE_HZ, self.publish_message)
        self.count = 0

    def publish_message(self) -> None:
        msg = String(data=f"hello world {self.count}")
        self.get_logger().info(msg.data)
        self.publisher.publish(msg)
        self.count += 1


def main() -> int:
    return run_node(Talker)


if __name__ == "__main__":
    raise SystemExit(main())
