"""Service server (book: ros_tutorials_service/service_server): serves SrvTutorial on
``ros_tutorial_srv``, answers each request with ``result = a + b`` and logs both.

    service_server         (or: python -m ros_tutorials_service.server)
"""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.srv import SrvTutorial


class ServiceServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("service_server", **node_kwargs)
        # The service server: service type, service name, the callback for each request.
        self.service = self.create_service(SrvTutorial, "ros_tutorial_srv", self.calculation)
        self.get_logger().info("ready srv server!")

    def calculation(
        self, request: SrvTutorial.Request, response: SrvTutorial.Response
    ) -> SrvTutorial.Response:
        a, b = request.a, request.b
        if -(2**63) <= a + b < 2**63:  # else 0: the response's int64 cannot hold the sum
            response.result = a + b
        else:
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
