"""The official tutorials' listener (ros2/demos, Jazzy: demo_nodes_cpp's listener), in Python.

Logs "I heard: [...]" for each std_msgs/String on ``chatter``:

    ros2 run demo_nodes_cpp listener
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import String

from ros_tutorials_common.ros import ros_args


class Listener(Node):
    def __init__(self) -> None:
        super().__init__("listener")
        self.subscription = self.create_subscription(String, "chatter", self.heard, 10)

    def heard(self, msg: String) -> None:
        self.get_logger().info(f"I heard: [{msg.data}]")


def main(args=None) -> None:
    rclpy.init(args=ros_args(args))  # initialise ROS 2 (reads --ros-args; DDS defaults)
    try:
        rclpy.spin(Listener())  # until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
