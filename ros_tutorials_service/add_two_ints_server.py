"""AddTwoInts server (the classic roscpp/rospy tutorial of seeds 001-004).

Serves ros_tutorials_interfaces/AddTwoInts on ``add_two_ints``: ``sum = a + b``.

    python -m ros_tutorials_service.add_two_ints_server     (or: add_two_ints_server)
"""

from rclpy.node import Node
from ros_tutorials_interfaces.srv import AddTwoInts

from ros_tutorials_common.int64 import int64_or_zero
from ros_tutorials_common.node_main import run_node


class AddTwoIntsServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("add_two_ints_server", enable_logger_service=True, **node_kwargs)
        self.service = self.create_service(AddTwoInts, "add_two_ints", self.add)
        self.get_logger().info("Ready to add two ints.")

    def add(
        self, request: AddTwoInts.Request, response: AddTwoInts.Response
    ) -> AddTwoInts.Response:
        log = self.get_logger()
        log.info(f"request: x={request.a}, y={request.b}")
        # Two large int64 operands can add up to more than an int64 holds.
        response.sum = int64_or_zero(request.a + request.b, f"{request.a} + {request.b}", log)
        log.info(f"sending back response: [{response.sum}]")
        return response


def main() -> int:
    return run_node(AddTwoIntsServer)


if __name__ == "__main__":
    raise SystemExit(main())
