"""Topic subscriber (book: ros_tutorials_topic/topic_subscriber).

Subscribes to ``ros_tutorial_msg`` and logs each message's stamp and data, as the book
does (its "recieve" typo included, so the output matches the printed listing).

    topic_subscriber       (or: python -m ros_tutorials_topic.subscriber)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import MsgTutorial

QUEUE_SIZE = 100


class TopicSubscriber(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("topic_subscriber", **node_kwargs)
        # The subscriber: message type, topic name, the callback for each message, queue size.
        self.subscription = self.create_subscription(
            MsgTutorial, "ros_tutorial_msg", self.on_message, QUEUE_SIZE
        )

    def on_message(self, msg: MsgTutorial) -> None:
        self.get_logger().info(f"recieve msg = {msg.stamp.sec}")
        self.get_logger().info(f"recieve msg = {msg.stamp.nanosec}")
        self.get_logger().info(f"recieve msg = {msg.data}")


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = TopicSubscriber()  # create the node
    try:
        rclpy.spin(node)  # wait for messages and call on_message for each, until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
