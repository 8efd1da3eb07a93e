"""Dynamics talker (seed 004's dynamics_talker): a talker whose text is a parameter.

Publishes std_msgs/String on ``chatter`` ten times a second; the text is the parameter
``talker_str`` (default "hello world"), read each time, so a change shows on the next message.

    python -m ros_tutorials_parameter.talker     (or: dynamics_talker)
    dynamics_talker --ros-args -p talker_str:=Goodbye
"""

from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node
from std_msgs.msg import String

from ros_tutorials_common.node_main import run_node

QUEUE_SIZE = 10
RATE_HZ = 10.0


class DynamicsTalker(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("dynamics_talker", enable_logger_service=True, **node_kwargs)
        self.declare_parameter(
            "talker_str", "hello world", ParameterDescriptor(description="the text to publish")
        )
        self.publisher = self.create_publisher(String, "chatter", QUEUE_SIZE)
        self.timer = self.create_timer(1.0 / RATE_HZ, self.publish_message)

    def publish_message(self) -> None:
        msg = String(data=self.get_parameter("talker_str").value)
        self.get_logger().info(msg.data)
        self.publisher.publish(msg)


def main() -> int:
    return run_node(DynamicsTalker)


if __name__ == "__main__":
    raise SystemExit(main())
