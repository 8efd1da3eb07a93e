"""A UserRecord subscriber: seed 004's own message, received like seed 004's listener.

Subscribes to ``user_record`` (``ros_tutorials_interfaces/msg/UserRecord``) and logs each
record: ``Receive : Ada Lovelace, age 36, score 0``. Node ``user_record_subscriber``.

    user_record_subscriber      (or: rosrun my_package user_record_subscriber)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import UserRecord


class UserRecordSubscriber(Node):
    def __init__(self) -> None:
        super().__init__("user_record_subscriber")
        self.subscription = self.create_subscription(UserRecord, "user_record", self.callback, 10)

    def callback(self, msg: UserRecord) -> None:
        self.get_logger().info(
            f"Receive : {msg.first_name} {msg.last_name}, age {msg.age}, score {msg.score}"
        )


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = UserRecordSubscriber()  # create the node
    try:
        rclpy.spin(node)  # until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
