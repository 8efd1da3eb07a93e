"""Service client (book: ros_tutorials_service/service_client): sends the two numbers of its
command line to ``ros_tutorial_srv`` once, logs the request and the result, and exits.

    service_client 2 3     (or: python -m ros_tutorials_service.client 2 3; --help)
"""

import argparse
import re
import sys

import rclpy
from rclpy.node import Node
from rclpy.utilities import remove_ros_args
from ros_tutorials_interfaces.srv import SrvTutorial


def int64(text: str) -> int:
    """An argparse type: a whole number as the book's atoll reads it (digits, a sign), in int64."""
    if not re.fullmatch(r"[+-]?[0-9]+", text):
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer")
    if not -(2**63) <= int(text) < 2**63:
        raise argparse.ArgumentTypeError(f"{text} does not fit in a 64-bit integer")
    return int(text)


def main(args: list[str] | None = None) -> int:
    # The command line, without the ROS arguments: A, B and --timeout; else usage, exit status 2.
    parser = argparse.ArgumentParser(prog="service_client")
    parser.add_argument("a", metavar="A", type=int64)
    parser.add_argument("b", metavar="B", type=int64)
    parser.add_argument("--timeout", metavar="SECONDS", type=float, default=5.0)
    options = parser.parse_args(remove_ros_args(args or sys.argv)[1:])
    timeout = options.timeout
    if not 0 < timeout <= 1e6:  # nan and inf too: rcl counts a wait in int64 nanoseconds
        parser.error(f"--timeout: {timeout:g} is not a positive number of seconds up to 1e6")

    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = Node("service_client", enable_logger_service=True)  # create the node
    client = node.create_client(SrvTutorial, "ros_tutorial_srv")  # and the service client
    log = node.get_logger()
    try:
        # Wait for the server, then for its answer: at most --timeout seconds each.
        if not client.wait_for_service(timeout_sec=timeout):
            log.error(f"Failed to call service {client.srv_name}: no server within {timeout:g} s")
            return 1
        request = SrvTutorial.Request(a=options.a, b=options.b)  # create the request
        future = client.call_async(request)  # call the service
        rclpy.spin_until_future_complete(node, future, timeout_sec=timeout)
        if not future.done():
            log.error(f"Failed to call service {client.srv_name}: no answer within {timeout:g} s")
            return 1
        response = future.result()  # read the response
        log.info(f"send srv, srv.Request.a and b: {request.a}, {request.b}")
        log.info(f"receive srv, srv.Response.result: {response.result}")
        return 0
    except KeyboardInterrupt:
        return 130  # Ctrl-C: the exit status a shell gives a command it interrupted
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    sys.exit(main())
