"""Service server with a parameter (book: ros_tutorials_parameter/service_server_with_parameter).

Serves SrvTutorial on ``ros_tutorial_srv`` like the service lesson's server, but the operator
is the parameter ``calculation_method``: 1 plus (default), 2 minus, 3 multiplication,
4 division. Set it at start or while the server runs; the next request uses it:

    service_server_with_parameter --ros-args -p calculation_method:=3
    service_server_with_parameter --ros-args \
        --params-file ros_tutorials_parameter/config/parameters.yaml
"""

import operator
import sys
from collections.abc import Callable

import rclpy
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor, SetParametersResult
from rclpy.exceptions import ParameterException
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.parameter import Parameter
from ros_tutorials_interfaces.srv import SrvTutorial

PLUS, MINUS, MULTIPLICATION, DIVISION = 1, 2, 3, 4
INT64_MIN, INT64_MAX = -(2**63), 2**63 - 1  # what the response's int64 field can hold


def divide(a: int, b: int) -> int:
    """Integer division as in the book's C++: rounds toward zero (Python's // rounds down)."""
    quotient = abs(a) // abs(b)
    return quotient if (a < 0) == (b < 0) else -quotient


# calculation_method -> (name, symbol for the log, function)
OPERATORS: dict[int, tuple[str, str, Callable[[int, int], int]]] = {
    PLUS: ("plus", "+", operator.add),
    MINUS: ("minus", "-", operator.sub),
    MULTIPLICATION: ("multiplication", "*", operator.mul),
    DIVISION: ("division", "/", divide),
}


class ServiceServerWithParameter(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("service_server", enable_logger_service=True, **node_kwargs)
        # The descriptor documents the parameter (ros2 param describe shows it) and makes
        # rclpy refuse other types and values outside 1..4, at start and at run time.
        descriptor = ParameterDescriptor(
            description="operator: 1 plus, 2 minus, 3 multiplication, 4 division",
            integer_range=[IntegerRange(from_value=PLUS, to_value=DIVISION, step=1)],
        )
        self.declare_parameter("calculation_method", PLUS, descriptor)
        self.add_on_set_parameters_callback(self.check_parameters)
        self.add_post_set_parameters_callback(self.log_parameters)
        self.service = self.create_service(SrvTutorial, "ros_tutorial_srv", self.calculation)
        self.get_logger().info("ready srv server!")

    def check_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        """Accept a new calculation_method only if it names one of OPERATORS."""
        # The descriptor's range already says 1..4; this keeps OPERATORS and the parameter
        # in step if one of them is ever changed without the other.
        for parameter in parameters:
            if parameter.name == "calculation_method" and parameter.value not in OPERATORS:
                choices = ", ".join(f"{key} ({name})" for key, (name, _, _) in OPERATORS.items())
                return SetParametersResult(
                    successful=False,
                    reason=f"calculation_method must be one of {choices}, not {parameter.value}",
                )
        return SetParametersResult(successful=True)

    def log_parameters(self, parameters: list[Parameter]) -> None:
        for parameter in parameters:
            if parameter.name == "calculation_method":
                name = OPERATORS[parameter.value][0]
                self.get_logger().info(f"calculation_method is now {parameter.value} ({name})")

    def calculation(
        self, request: SrvTutorial.Request, response: SrvTutorial.Response
    ) -> SrvTutorial.Response:
        # Read the parameter on every request, so a change takes effect on the next one.
        method = self.get_parameter("calculation_method").value
        _, symbol, function = OPERATORS[method]
        a, b = request.a, request.b
        log = self.get_logger()
        log.info(f"request: x={a}, y={b}")
        if method == DIVISION and b == 0:
            log.warning(f"division by zero ({a} / 0); sending back 0")
            response.result = 0
        else:
            # a + b, a - b and a * b can leave the int64 range, and so can INT64_MIN / -1.
            result = function(a, b)
            response.result = result if INT64_MIN <= result <= INT64_MAX else 0
            if response.result != result:
                log.warning(f"{a} {symbol} {b} = {result} does not fit in int64; sending back 0")
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
