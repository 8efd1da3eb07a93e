"""AddTwoInts client (the classic roscpp/rospy tutorial of seeds 001-004).

Asks ``add_two_ints`` for X + Y once and logs "Sum: ...". Without a server it waits up to
``--timeout`` seconds (default 5), then fails with exit status 1.

    python -m ros_tutorials_service.add_two_ints_client 1 2   (or: add_two_ints_client 1 2)
"""

from rclpy.node import Node
from ros_tutorials_interfaces.srv import AddTwoInts

from ros_tutorials_common.service_client import call_once


class AddTwoIntsClient(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("add_two_ints_client", enable_logger_service=True, **node_kwargs)
        self.client = self.create_client(AddTwoInts, "add_two_ints")

    def report(self, request: AddTwoInts.Request, response: AddTwoInts.Response) -> None:
        self.get_logger().info(f"Sum: {response.sum}")


def main() -> int:
    return call_once(AddTwoIntsClient, "add_two_ints_client", operands=("X", "Y"))


if __name__ == "__main__":
    raise SystemExit(main())
