"""A UserRecord subscriber: seed 004's own message, received like seed 004's listener.

Subscribes to ``user_record`` (``ros_tutorials_interfaces/msg/UserRecord``) and logs each
record: ``Receive : Ada Lovelace, age 36, score 0``. Node ``user_record_subscriber``.

    user_record_subscriber      (or: rosrun my_package user_record_subscriber)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import UserRecord

from ros_tutorials_common.ros import ros_args


class UserRecordSubscriber(Node):
    def __init__(self) -> None:
        super().__init__("user_record_subscriber", enable_logger_service=True)
        self.subscription = self.create_subscription(UserRecord, "user_record", self.callback, 10)

    def callback(self, msg: UserRecord) -> None:
        self.get_logger().info(
            f"Receive : {msg.first_name} {msg.last_name}, age {msg.age}, score {msg.score}"
        )


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=ros_args(args))  # initialise ROS 2 (reads --ros-args; DDS defaults)
    node = UserRecordSubscriber()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or shutdown: a normal end
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
