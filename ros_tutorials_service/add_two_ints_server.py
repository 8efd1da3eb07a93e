"""AddTwoInts server (the classic tutorial of seeds 001-004): serves ``add_two_ints``, a + b."""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.srv import AddTwoInts


class AddTwoIntsServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("add_two_ints_server", **node_kwargs)
        self.service = self.create_service(AddTwoInts, "add_two_ints", self.add)
        self.get_logger().info("Ready to add two ints.")

    def add(self, request, response: AddTwoInts.Response) -> AddTwoInts.Response:
        a, b = request.a, request.b
        if -(2**63) <= a + b < 2**63:  # else 0: the response's int64 cannot hold the sum
            response.sum = a + b
        else:
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
