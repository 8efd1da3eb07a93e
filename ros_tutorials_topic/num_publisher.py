"""The Num publisher of seed 003 (package pub_sub, executable publisher): a custom message.

Publishes ``ros_tutorials_interfaces/msg/Num`` (``int64 num``) on ``publisher`` ten times a
second, counting 1, 2, ... 999, 0, 1, ... as the seed's pub.cpp (``i = (i + 1) % 1000``).
Node ``pub``. Like the seed's, it logs nothing: watch it with ``rostopic echo /publisher``.

    num_publisher       (or: rosrun pub_sub publisher)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.msg import Num


class NumPublisher(Node):
    def __init__(self) -> None:
        super().__init__("pub")
        self.publisher = self.create_publisher(Num, "publisher", 1000)
        self.timer = self.create_timer(0.1, self.publish_message)  # 10 Hz
        self.i = 0

    def publish_message(self) -> None:
        self.i = (self.i + 1) % 1000
        msg = Num()
        msg.num = self.i
        self.publisher.publish(msg)


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = NumPublisher()  # create the node
    try:
        rclpy.spin(node)  # until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
