"""Topic publisher (book: ros_tutorials_topic/topic_publisher).

Publishes ros_tutorials_interfaces/MsgTutorial on ``ros_tutorial_msg`` ten times a second:
the current time as ``stamp`` and a counter, from 0, as ``data``.

    python -m ros_tutorials_topic.publisher      (or: topic_publisher)
"""

from rclpy.node import Node
from ros_tutorials_interfaces.msg import MsgTutorial

from ros_tutorials_common.node_main import run_node

QUEUE_SIZE = 100
RATE_HZ = 10.0


class TopicPublisher(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("topic_publisher", enable_logger_service=True, **node_kwargs)
        self.publisher = self.create_publisher(MsgTutorial, "ros_tutorial_msg", QUEUE_SIZE)
        self.timer = self.create_timer(1.0 / RATE_HZ, self.publish_message)
        self.count = 0

    def publish_message(self) -> None:
        msg = MsgTutorial()
        msg.stamp = self.get_clock().now().to_msg()
        msg.data = self.count
        self.publisher.publish(msg)
        log = self.get_logger()
        log.info(f"send msg = {msg.stamp.sec}")
        log.info(f"send msg = {msg.stamp.nanosec}")
        log.info(f"send msg = {msg.data}")
        self.count += 1


def main() -> int:
    return run_node(TopicPublisher)


if __name__ == "__main__":
    raise SystemExit(main())
