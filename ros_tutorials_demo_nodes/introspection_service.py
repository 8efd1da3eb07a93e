"""The service introspection demo's server (ros2/demos, Jazzy: demo_nodes_cpp's
introspection_service), in Python.

Serves example_interfaces/srv/AddTwoInts on ``add_two_ints`` (``sum = a + b``). Its parameter
``service_configure_introspection`` (``disabled``, ``metadata`` or ``contents``; default
``disabled``) says what the service tells about each request and response on the hidden topic
``/add_two_ints/_service_event``, which ``ros2 service echo /add_two_ints`` shows:

    ros2 run demo_nodes_cpp introspection_service
    ros2 param set /introspection_service service_configure_introspection contents
    ros2 run demo_nodes_cpp introspection_service \
        --ros-args -p service_configure_introspection:=contents
"""

import rclpy
from example_interfaces.srv import AddTwoInts
from rcl_interfaces.msg import SetParametersResult
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import qos_profile_system_default
from rclpy.service_introspection import ServiceIntrospectionState

PARAMETER = "service_configure_introspection"
STATES = {
    "disabled": ServiceIntrospectionState.OFF,
    "metadata": ServiceIntrospectionState.METADATA,
    "contents": ServiceIntrospectionState.CONTENTS,
}


class IntrospectionServiceNode(Node):
    def __init__(self) -> None:
        super().__init__("introspection_service")
        # Create a service that answers each request with add_two_ints().
        self.srv = self.create_service(AddTwoInts, "add_two_ints", self.add_two_ints)
        # Check a new value first; once it is set, configure introspection with it. The
        # declaration sets the value too (a `-p` at start-up), so the callbacks come first.
        self.add_on_set_parameters_callback(self.check_parameter)
        self.add_post_set_parameters_callback(self.configure_introspection)
        self.declare_parameter(PARAMETER, "disabled")

    def add_two_ints(
        self, request: AddTwoInts.Request, response: AddTwoInts.Response
    ) -> AddTwoInts.Response:
        self.get_logger().info(f"Incoming request\na: {request.a} b: {request.b}")
        response.sum = request.a + request.b
        return response

    def check_parameter(self, parameters: list[Parameter]) -> SetParametersResult:
        result = SetParametersResult(successful=True)
        for parameter in parameters:
            if parameter.name != PARAMETER:
                continue
            if parameter.type_ != Parameter.Type.STRING:
                result.successful, result.reason = False, "must be a string"
            elif parameter.value not in STATES:
                result.successful = False
                result.reason = "must be one of 'disabled', 'metadata', or 'contents'"
            break
        return result

    def configure_introspection(self, parameters: list[Parameter]) -> None:
        for parameter in parameters:
            if parameter.name == PARAMETER:
                self.srv.configure_introspection(
                    self.get_clock(), qos_profile_system_default, STATES[parameter.value]
                )
                break


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = IntrospectionServiceNode()  # create the node
    try:
        rclpy.spin(node)  # answer requests until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
