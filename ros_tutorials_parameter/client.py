"""Service client for the parameter lesson (book: ros_tutorials_parameter/service_client): the
book's client is the service lesson's, and so is this one, under this lesson's name. Its result
now depends on the server's parameter ``calculation_method``.

    service_client_with_parameter 10 5   (or: python -m ros_tutorials_parameter.client 10 5)
"""

import argparse
import sys

import rclpy
from rclpy.node import Node
from rclpy.utilities import remove_ros_args
from ros_tutorials_interfaces.srv import SrvTutorial


def main(args: list[str] | None = None) -> int:
    # The command line without the ROS arguments: A, B and --timeout (else usage, status 2).
    parser = argparse.ArgumentParser(prog="service_client_with_parameter")
    parser.add_argument("a", metavar="A", type=int)
    parser.add_argument("b", metavar="B", type=int)
    parser.add_argument("--timeout", metavar="SECONDS", type=float, default=5.0)
    options = parser.parse_args(remove_ros_args(args or sys.argv)[1:])
    if not all(-(2**63) <= n < 2**63 for n in (options.a, options.b)):
        parser.error("A and B must fit in int64")  # else rclpy fails with a SystemError
    if not 0 < options.timeout <= 3600:  # rclpy needs a finite wait
        parser.error("--timeout must be more than 0 and at most 3600 seconds")

    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = Node("service_client")  # create the node
    client = node.create_client(SrvTutorial, "ros_tutorial_srv")  # and the service client
    log = node.get_logger()
    try:
        # Wait for the server, then for its answer: at most --timeout seconds each.
        if client.wait_for_service(timeout_sec=options.timeout):
            request = SrvTutorial.Request(a=options.a, b=options.b)  # create the request
            future = client.call_async(request)  # call the service
            rclpy.spin_until_future_complete(node, future, timeout_sec=options.timeout)
            if future.done():
                log.info(f"send srv, srv.Request.a and b: {request.a}, {request.b}")
                log.info(f"receive srv, srv.Response.result: {future.result().result}")
                return 0
        failed = "no answer" if client.service_is_ready() else "no server"
        log.error(f"Failed to call service ros_tutorial_srv: {failed} within {options.timeout:g} s")
        return 1
    except KeyboardInterrupt:
        return 130  # Ctrl-C: the exit status a shell gives a command it interrupted
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    sys.exit(main())
