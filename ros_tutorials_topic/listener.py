"""Listener (the classic roscpp/rospy tutorial of seeds 001, 003, 004).

Subscribes to ``chatter`` (std_msgs/String) and logs "I heard: [...]" for each message.

    python -m ros_tutorials_topic.listener       (or: listener)
"""

from rclpy.node import Node
from std_msgs.msg import String

from ros_tutorials_common.node_main import run_node

QUEUE_SIZE = 1000


class Listener(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("listener", enable_logger_service=True, **node_kwargs)
        self.subscription = self.create_subscription(String, "chatter", self.on_message, QUEUE_SIZE)

    def on_message(self, msg: String) -> None:
        self.get_logger().info(f"I heard: [{msg.data}]")


def main() -> int:
    return run_node(Listener)


if __name__ == "__main__":
    raise SystemExit(main())
