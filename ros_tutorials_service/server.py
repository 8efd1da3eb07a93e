"""Service server (book: ros_tutorials_service/service_server).

Serves ros_tutorials_interfaces/SrvTutorial on ``ros_tutorial_srv``: answers each request
with ``result = a + b`` and logs the request and the response.

    python -m ros_tutorials_service.server       (or: service_server)
"""

from rclpy.node import Node
from ros_tutorials_interfaces.srv import SrvTutorial

from ros_tutorials_common.int64 import int64_or_zero
from ros_tutorials_common.node_main import run_node


class ServiceServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("service_server", enable_logger_service=True, **node_kwargs)
        self.service = self.create_service(SrvTutorial, "ros_tutorial_srv", self.calculation)
        self.get_logger().info("ready srv server!")

    def calculation(
        self, request: SrvTutorial.Request, response: SrvTutorial.Response
    ) -> SrvTutorial.Response:
        log = self.get_logger()
        log.info(f"request: x={request.a}, y={request.b}")
        # Two large int64 operands can add up to more than an int64 holds.
        response.result = int64_or_zero(request.a + request.b, f"{request.a} + {request.b}", log)
        log.info(f"sending back response: {response.result}")
        return response


def main() -> int:
    return run_node(ServiceServer)


if __name__ == "__main__":
    raise SystemExit(main())
