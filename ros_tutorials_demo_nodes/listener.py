"""The official tutorials' listener (ros2/demos, Jazzy: demo_nodes_cpp's listener), in Python.

Logs "I heard: [...]" for each std_msgs/String on ``chatter``:

    ros2 run demo_nodes_cpp listener
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import String


class Listener(Node):
    def __init__(self) -> None:
        super().__init__("listener")
        self.subscription = self.create_subscription(String, "chatter", self.heard, 10)

    def heard(self, msg: String) -> None:
        self.get_logger().info(f"I heard: [{msg.data}]")


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = Listener()  # create the node
    try:
        rclpy.spin(node)  # until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
