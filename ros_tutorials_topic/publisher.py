"""Topic publisher (book: ros_tutorials_topic/topic_publisher).

Publishes ros_tutorials_interfaces/MsgTutorial on ``ros_tutorial_msg`` ten times a second:
the current time as ``stamp`` and a counter, from 0, as ``data``.

    topic_publisher        (or: python -m ros_tutorials_topic.publisher)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import MsgTutorial


class TopicPublisher(Node):
    def __init__(self, **node_kwargs) -> None:
        # enable_logger_service: serve get/set_logger_levels, so that rqt_logger_level can
        # change this node's log level while it runs (docs/rqt-and-logging.md).
        super().__init__("topic_publisher", enable_logger_service=True, **node_kwargs)
        # The publisher: message type, topic name, queue size.
        self.publisher = self.create_publisher(MsgTutorial, "ros_tutorial_msg", 100)
        self.timer = self.create_timer(0.1, self.publish_message)  # 10 Hz, the book's loop rate
        self.count = 0

    def publish_message(self) -> None:
        msg = MsgTutorial()
        msg.stamp = self.get_clock().now().to_msg()  # the current time
        msg.data = self.count  # and the counter
        self.get_logger().info(f"send msg = {msg.stamp.sec}")
        self.get_logger().info(f"send msg = {msg.stamp.nanosec}")
        self.get_logger().info(f"send msg = {msg.data}")
        self.publisher.publish(msg)
        self.count += 1


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = TopicPublisher()  # create the node
    try:
        rclpy.spin(node)  # run its timer until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
