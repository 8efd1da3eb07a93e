"""Topic subscriber (book: ros_tutorials_topic/topic_subscriber).

Subscribes to ``ros_tutorial_msg`` and logs each message's stamp and data, as the book
does (its "recieve" typo included, so the output matches the printed listing).

    python -m ros_tutorials_topic.subscriber     (or: topic_subscriber)
"""

from rclpy.node import Node
from ros_tutorials_interfaces.msg import MsgTutorial

from ros_tutorials_common.node_main import run_node

QUEUE_SIZE = 100


class TopicSubscriber(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("topic_subscriber", enable_logger_service=True, **node_kwargs)
        self.subscription = self.create_subscription(
            MsgTutorial, "ros_tutorial_msg", self.on_message, QUEUE_SIZE
        )

    def on_message(self, msg: MsgTutorial) -> None:
        log = self.get_logger()
        log.info(f"recieve msg = {msg.stamp.sec}")
        log.info(f"recieve msg = {msg.stamp.nanosec}")
        log.info(f"recieve msg = {msg.data}")


def main() -> int:
    return run_node(TopicSubscriber)


if __name__ == "__main__":
    raise SystemExit(main())
