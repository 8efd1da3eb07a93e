"""Dynamics talker (seed 004's dynamics_talker): publishes on ``chatter`` ten times a second
the parameter ``talker_str`` (default "hello world"), read each time, so a change shows at once.

    dynamics_talker --ros-args -p talker_str:=Goodbye   (python -m ros_tutorials_parameter.talker)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import String


class DynamicsTalker(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("dynamics_talker", **node_kwargs)
        self.declare_parameter("talker_str", "hello world")  # its name and default
        self.publisher = self.create_publisher(String, "chatter", 10)  # queue_size=10
        self.timer = self.create_timer(0.1, self.publish_message)  # 10 Hz

    def publish_message(self) -> None:
        msg = String(data=self.get_parameter("talker_str").value)  # read on every message
        self.get_logger().info(msg.data)
        self.publisher.publish(msg)


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args -p ...)
    node = DynamicsTalker()  # create the node: it declares talker_str
    try:
        rclpy.spin(node)  # run its timer until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
