"""AddTwoInts server (the classic rospy/roscpp tutorial of seeds 001-004).

Serves ros_tutorials_interfaces/AddTwoInts on ``add_two_ints``: ``sum = a + b``.

    add_two_ints_server    (or: python -m ros_tutorials_service.add_two_ints_server)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.srv import AddTwoInts

from ros_tutorials_common.int64 import int64_or_zero
from ros_tutorials_common.ros import ros_args


class AddTwoIntsServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("add_two_ints_server", enable_logger_service=True, **node_kwargs)
        self.service = self.create_service(AddTwoInts, "add_two_ints", self.add)
        self.get_logger().info("Ready to add two ints.")

    def add(
        self, request: AddTwoInts.Request, response: AddTwoInts.Response
    ) -> AddTwoInts.Response:
        # a + b (two large int64 operands may add up to more than int64 holds)
        a, b = request.a, request.b
        response.sum = int64_or_zero(a + b, f"{a} + {b}", self.get_logger())
        self.get_logger().info(f"request: x={a}, y={b}")
        self.get_logger().info(f"sending back response: [{response.sum}]")
        return response


def main(args=None) -> None:
    rclpy.init(args=ros_args(args))  # initialise ROS 2 (reads --ros-args; DDS defaults)
    try:
        rclpy.spin(AddTwoIntsServer())  # create the node and answer requests until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
