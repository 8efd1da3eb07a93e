"""A small node for the rostool tests: a SrvTutorial service, a parameter, a Fibonacci action.

It stands in for the service, parameter and action lessons (written on other branches) with
the names the book uses: node ``service_server``, service ``ros_tutorial_srv``, parameter
``calculation_method`` (1 plus, 2 minus, 3 multiply, 4 divide; 1..4 enforced by its
descriptor), action ``ros_tutorial_action``. Run as a process by the tests:

    python tests/rostool_fixture_node.py [--ros-args -r __node:=other_name]
"""

import time

from rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from rclpy.action import ActionServer
from rclpy.node import Node
from ros_tutorials_interfaces.action import Fibonacci
from ros_tutorials_interfaces.srv import SrvTutorial

from ros_tutorials_common.node_main import run_node

STEP_PERIOD = 0.1


class FixtureNode(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("service_server", **node_kwargs)
        descriptor = ParameterDescriptor(
            integer_range=[IntegerRange(from_value=1, to_value=4, step=1)]
        )
        self.declare_parameter("calculation_method", 1, descriptor)
        self.create_service(SrvTutorial, "ros_tutorial_srv", self.calculate)
        self.action_server = ActionServer(self, Fibonacci, "ros_tutorial_action", self.fibonacci)
        self.get_logger().info("fixture ready")

    def calculate(self, request: SrvTutorial.Request, response: SrvTutorial.Response):
        method = self.get_parameter("calculation_method").value
        a, b = request.a, request.b
        results = {1: a + b, 2: a - b, 3: a * b, 4: a // b if b else 0}
        response.result = results[method]
        return response

    def fibonacci(self, goal_handle):
        sequence = [0, 1]
        for _ in range(1, goal_handle.request.order):
            time.sleep(STEP_PERIOD)  # like the book's server (1 Hz there), only faster
            sequence.append(sequence[-1] + sequence[-2])
            goal_handle.publish_feedback(Fibonacci.Feedback(sequence=sequence))
        goal_handle.succeed()
        return Fibonacci.Result(sequence=sequence)


if __name__ == "__main__":
    raise SystemExit(run_node(FixtureNode))
