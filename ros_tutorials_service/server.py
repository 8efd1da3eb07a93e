"""Service server (book: ros_tutorials_service/service_server).

Serves ros_tutorials_interfaces/SrvTutorial on ``ros_tutorial_srv``: answers each request
with ``result = a + b`` and logs the request and the response.

    service_server         (or: python -m ros_tutorials_service.server)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.srv import SrvTutorial

from ros_tutorials_common.int64 import int64_or_zero
from ros_tutorials_common.ros import ros_args


class ServiceServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("service_server", enable_logger_service=True, **node_kwargs)
        # The service server: service type, service name, the callback for each request.
        self.service = self.create_service(SrvTutorial, "ros_tutorial_srv", self.calculation)
        self.get_logger().info("ready srv server!")

    def calculation(
        self, request: SrvTutorial.Request, response: SrvTutorial.Response
    ) -> SrvTutorial.Response:
        # a + b into the response (two large int64 operands may add up to more than int64 holds)
        a, b = request.a, request.b
        response.result = int64_or_zero(a + b, f"{a} + {b}", self.get_logger())
        self.get_logger().info(f"request: x={request.a}, y={request.b}")
        self.get_logger().info(f"sending back response: {response.result}")
        return response


def main(args=None) -> None:
    rclpy.init(args=ros_args(args))  # initialise ROS 2 (reads --ros-args; DDS defaults)
    try:
        node = ServiceServer()  # create the node and its service
        rclpy.spin(node)  # wait for requests and answer each, until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
