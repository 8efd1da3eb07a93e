"""Service server (book: ros_tutorials_service/service_server).

Serves ros_tutorials_interfaces/SrvTutorial on ``ros_tutorial_srv``: answers each request
with ``result = a + b`` and logs the request and the response.

    service_server         (or: python -m ros_tutorials_service.server)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.srv import SrvTutorial

INT64_MIN, INT64_MAX = -(2**63), 2**63 - 1  # what the response's int64 field can hold


class ServiceServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("service_server", enable_logger_service=True, **node_kwargs)
        # The service server: service type, service name, the callback for each request.
        self.service = self.create_service(SrvTutorial, "ros_tutorial_srv", self.calculation)
        self.get_logger().info("ready srv server!")

    def calculation(
        self, request: SrvTutorial.Request, response: SrvTutorial.Response
    ) -> SrvTutorial.Response:
        a, b = request.a, request.b
        # a + b; two large int64 operands can add up to more than int64 holds: then 0, and why.
        response.result = a + b if INT64_MIN <= a + b <= INT64_MAX else 0
        if response.result != a + b:
            self.get_logger().warning(f"{a} + {b} = {a + b} does not fit in int64; sending back 0")
        self.get_logger().info(f"request: x={a}, y={b}")
        self.get_logger().info(f"sending back response: {response.result}")
        return response


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = ServiceServer()  # create the node
    try:
        rclpy.spin(node)  # wait for requests and answer each, until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
