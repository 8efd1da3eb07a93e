"""The service introspection demo's client (ros2/demos, Jazzy: demo_nodes_cpp's
introspection_client), in Python.

Every half second, once the server is there and no request is waiting for its answer, asks
``add_two_ints`` (example_interfaces/srv/AddTwoInts) for 2 + 3 and logs the result. Its
parameter ``client_configure_introspection`` (``disabled``, ``metadata`` or ``contents``;
default ``disabled``) says what the client tells about each request and response on
``/add_two_ints/_service_event`` (see ``ros2 service echo``):

    ros2 run demo_nodes_cpp introspection_client
    ros2 param set /introspection_client client_configure_introspection contents
"""

import rclpy
from example_interfaces.srv import AddTwoInts
from rcl_interfaces.msg import SetParametersResult
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import qos_profile_system_default
from rclpy.service_introspection import ServiceIntrospectionState
from rclpy.task import Future

PARAMETER = "client_configure_introspection"
STATES = {
    "disabled": ServiceIntrospectionState.OFF,
    "metadata": ServiceIntrospectionState.METADATA,
    "contents": ServiceIntrospectionState.CONTENTS,
}


class IntrospectionClientNode(Node):
    def __init__(self) -> None:
        super().__init__("introspection_client")
        self.client = self.create_client(AddTwoInts, "add_two_ints")
        # Check a new value first; once it is set, configure introspection with it. The
        # declaration sets the value too (a `-p` at start-up), so the callbacks come first.
        self.add_on_set_parameters_callback(self.check_parameter)
        self.add_post_set_parameters_callback(self.configure_introspection)
        self.declare_parameter(PARAMETER, "disabled")
        self.request_in_progress = False
        self.timer = self.create_timer(0.5, self.send_request)

    def send_request(self) -> None:
        if not self.client.service_is_ready() or self.request_in_progress:
            return
        request = AddTwoInts.Request(a=2, b=3)
        self.request_in_progress = True
        self.client.call_async(request).add_done_callback(self.log_result)

    def log_result(self, future: Future) -> None:
        self.request_in_progress = False
        self.get_logger().info(f"Result of add_two_ints: {future.result().sum}")

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
                self.client.configure_introspection(
                    self.get_clock(), qos_profile_system_default, STATES[parameter.value]
                )
                break


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = IntrospectionClientNode()  # create the node
    try:
        rclpy.spin(node)  # ask every half second until Ctrl-C
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
