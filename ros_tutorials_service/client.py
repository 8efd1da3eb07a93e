"""Service client (book: ros_tutorials_service/service_client): sends the two numbers of its
command line to ``ros_tutorial_srv`` once, logs the request and the result, and exits.

    service_client 2 3     (or: python -m ros_tutorials_service.client 2 3; --help)
"""

import sys

import rclpy
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from ros_tutorials_interfaces.srv import SrvTutorial

from ros_tutorials_common.ros import service_client_steps as steps


def main(args=None, prog: str = "service_client") -> int:
    # The command line: A and B (int64) and --timeout; anything else: usage, exit status 2.
    options = steps.parse_args(args, prog, "A", "B")
    # Ctrl-C raises KeyboardInterrupt below, and ROS stays up until we shut it down.
    rclpy.init(args=steps.ros_args(args), signal_handler_options=SignalHandlerOptions.NO)
    node = Node("service_client", enable_logger_service=True)  # create the node
    client = node.create_client(SrvTutorial, "ros_tutorial_srv")  # and the service client
    try:
        # Wait for the server, then for the answer: at most --timeout seconds each.
        if not steps.wait_for_service(node, client, options.timeout):
            return 1
        request = SrvTutorial.Request(a=options.a, b=options.b)  # create the request
        future = client.call_async(request)  # call the service
        if not steps.wait_for_answer(node, client, future, options.timeout):
            return 1
        response = future.result()  # read the response
        node.get_logger().info(f"send srv, srv.Request.a and b: {request.a}, {request.b}")
        node.get_logger().info(f"receive srv, srv.Response.result: {response.result}")
        return 0
    except KeyboardInterrupt:
        return steps.interrupted(prog)  # Ctrl-C: exit status 130
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    sys.exit(main())
