"""The AandB talker of seed 002: its own message type on ``chatter``.

Publishes ``ros_tutorials_interfaces/msg/AandB`` (``float32 a``, ``float32 b``) ten times a
second, a = 1.0 and b = 2.0, and logs each as the seed's talker.cpp does:
``msg a: 1.000000, msg b:2.000000``. Node ``talker``, topic ``chatter``, as in the seed (so
it cannot share ``chatter`` with the std_msgs/String talker; remap one: ``-r chatter:=ab``).

    aandb_talker        (or: rosrun beginner_tutorials aandb_talker)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import AandB


class AandBTalker(Node):
    def __init__(self) -> None:
        super().__init__("talker")
        # Publish AandB on chatter, keeping up to 1000 messages for slow subscribers.
        self.publisher = self.create_publisher(AandB, "chatter", 1000)
        # Ten times a second, as ros::Rate loop_rate(10).
        self.timer = self.create_timer(0.1, self.publish_message)

    def publish_message(self) -> None:
        msg = AandB()
        msg.a = 1.0
        msg.b = 2.0
        self.get_logger().info(f"msg a: {msg.a:.6f}, msg b:{msg.b:.6f}")
        self.publisher.publish(msg)


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = AandBTalker()  # create the node
    try:
        rclpy.spin(node)  # until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
