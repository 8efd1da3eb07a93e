"""Service server with a parameter (book: ros_tutorials_parameter/service_server_with_parameter).

Serves SrvTutorial on ``ros_tutorial_srv`` like the service lesson's server, but the operator
is the parameter ``calculation_method``: 1 plus (default), 2 minus, 3 multiplication,
4 division. Set it at start or while the server runs; the next request uses it:

    service_server_with_parameter --ros-args -p calculation_method:=3
    service_server_with_parameter --ros-args \
        --params-file ros_tutorials_parameter/config/parameters.yaml
"""

import sys

import rclpy
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from rclpy.exceptions import ParameterException
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from ros_tutorials_interfaces.srv import SrvTutorial

PLUS, MINUS, MULTIPLICATION, DIVISION = 1, 2, 3, 4


class ServiceServerWithParameter(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("service_server", **node_kwargs)
        # The descriptor documents the parameter (ros2 param describe shows it) and makes
        # rclpy refuse other types and values outside 1..4, at start and at run time.
        descriptor = ParameterDescriptor(
            description="operator: 1 plus, 2 minus, 3 multiplication, 4 division",
            integer_range=[IntegerRange(from_value=PLUS, to_value=DIVISION, step=1)],
        )
        self.declare_parameter("calculation_method", PLUS, descriptor)
        self.service = self.create_service(SrvTutorial, "ros_tutorial_srv", self.calculation)
        self.get_logger().info("ready srv server!")

    def calculation(self, request, response: SrvTutorial.Response) -> SrvTutorial.Response:
        # Read the parameter on every request, so a change takes effect on the next one.
        method = self.get_parameter("calculation_method").value
        a, b = request.a, request.b
        log = self.get_logger()
        log.info(f"request: x={a}, y={b}")
        if method == PLUS:
            result = a + b
        elif method == MINUS:
            result = a - b
        elif method == MULTIPLICATION:
            result = a * b
        elif b != 0:  # division rounds toward zero, as in the book's C++ (Python's // rounds down)
            result = abs(a) // abs(b) * (1 if (a < 0) == (b < 0) else -1)
        else:
            log.warning(f"division by zero ({a} / 0); sending back 0")
            result = 0
        if -(2**63) <= result < 2**63:  # else 0: the response's int64 cannot hold it
            response.result = result
        else:
            expression = f"{a} {' +-*/'[method]} {b} = {result}"
            log.warning(f"{expression} does not fit in int64; sending back 0")
        log.info(f"sending back response: [{response.result}]")
        return response


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args -p ...)
    try:
        node = ServiceServerWithParameter()  # create the node: it declares the parameter
    except ParameterException as error:  # e.g. -p calculation_method:=7
        rclpy.try_shutdown()
        sys.exit(f"error: {error}")
    try:
        rclpy.spin(node)  # answer requests until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
