"""A UserRecord publisher: seed 004's own message, sent like seed 004's talker.

Publishes ``ros_tutorials_interfaces/msg/UserRecord`` (``string first_name``, ``string
last_name``, ``uint8 age``, ``uint32 score``) on ``user_record`` ten times a second, the score
counting up from 0, and logs each: ``first_name: Ada, last_name: Lovelace, age: 36, score: 0``.
Node ``user_record_publisher``.

    user_record_publisher       (or: rosrun my_package user_record_publisher)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import UserRecord


class UserRecordPublisher(Node):
    def __init__(self) -> None:
        super().__init__("user_record_publisher")
        self.publisher = self.create_publisher(UserRecord, "user_record", 10)
        self.timer = self.create_timer(0.1, self.publish_record)  # 10 Hz, as rospy.Rate(10)
        self.score = 0

    def publish_record(self) -> None:
        # A message is built like any Python object: fields by keyword, or one by one.
        msg = UserRecord(first_name="Ada", last_name="Lovelace", age=36)
        msg.score = self.score
        self.get_logger().info(
            f"first_name: {msg.first_name}, last_name: {msg.last_name}, "
            f"age: {msg.age}, score: {msg.score}"
        )
        self.publisher.publish(msg)
        self.score += 1


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = UserRecordPublisher()  # create the node
    try:
        rclpy.spin(node)  # until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
