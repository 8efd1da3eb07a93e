"""AddTwoInts server (the classic rospy/roscpp tutorial of seeds 001-004).

Serves ros_tutorials_interfaces/AddTwoInts on ``add_two_ints``: ``sum = a + b``.

    add_two_ints_server    (or: python -m ros_tutorials_service.add_two_ints_server)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.srv import AddTwoInts

INT64_MIN, INT64_MAX = -(2**63), 2**63 - 1  # what the response's int64 field can hold


class AddTwoIntsServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("add_two_ints_server", enable_logger_service=True, **node_kwargs)
        self.service = self.create_service(AddTwoInts, "add_two_ints", self.add)
        self.get_logger().info("Ready to add two ints.")

    def add(
        self, request: AddTwoInts.Request, response: AddTwoInts.Response
    ) -> AddTwoInts.Response:
        a, b = request.a, request.b
        # a + b; two large int64 operands can add up to more than int64 holds: then 0, and why.
        response.sum = a + b if INT64_MIN <= a + b <= INT64_MAX else 0
        if response.sum != a + b:
            self.get_logger().warning(f"{a} + {b} = {a + b} does not fit in int64; sending back 0")
        self.get_logger().info(f"request: x={a}, y={b}")
        self.get_logger().info(f"sending back response: [{response.sum}]")
        return response


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = AddTwoIntsServer()  # create the node
    try:
        rclpy.spin(node)  # answer requests until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
