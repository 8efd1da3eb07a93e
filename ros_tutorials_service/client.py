"""Service client (book: ros_tutorials_service/service_client).

Sends the two numbers of its command line to ``ros_tutorial_srv`` once, logs the request and
the result, and exits.

    service_client 2 3     (or: python -m ros_tutorials_service.client 2 3)

Exit status: 0 answered; 1 no server, or no answer, within --timeout seconds (default 5);
2 usage error (not two int64 integers); 130 Ctrl-C.
"""

import argparse
import sys
import time

import rclpy
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from ros_tutorials_interfaces.srv import SrvTutorial

from ros_tutorials_common.cli import EXIT_INTERRUPTED, positive_seconds, signed_int
from ros_tutorials_common.ros import ros_args, user_args


def parse_args(args: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="service_client", description="Call ros_tutorial_srv once with A and B."
    )
    parser.add_argument("a", metavar="A", type=signed_int(64), help="first operand (int64)")
    parser.add_argument("b", metavar="B", type=signed_int(64), help="second operand (int64)")
    parser.add_argument(
        "--timeout", metavar="SECONDS", type=positive_seconds, default=5.0,
        help="how long to wait for the server, then for its answer (default 5)",
    )  # fmt: skip
    return parser.parse_args(args)


def main(args=None) -> int:
    options = parse_args(user_args(args))  # bad arguments: usage and exit status 2
    # Ctrl-C raises KeyboardInterrupt below, and ROS stays up until we shut it down.
    rclpy.init(args=ros_args(args), signal_handler_options=SignalHandlerOptions.NO)
    node = Node("service_client", enable_logger_service=True)  # create the node
    client = node.create_client(SrvTutorial, "ros_tutorial_srv")  # and the service client
    log, timeout = node.get_logger(), options.timeout
    try:
        # Wait for the server; say so if it takes more than a second.
        if not client.wait_for_service(timeout_sec=min(1.0, timeout)):
            log.info(f"waiting for service ros_tutorial_srv (up to {timeout:g} s)...")
            if not client.wait_for_service(timeout_sec=timeout - 1.0):
                log.error(
                    f"Failed to call service ros_tutorial_srv: no server within {timeout:g} s"
                )
                return 1
        request = SrvTutorial.Request(a=options.a, b=options.b)  # create the request
        future = client.call_async(request)  # call the service
        end = time.monotonic() + timeout  # wait for the answer, spinning in short slices
        while not future.done() and time.monotonic() < end:  # (Ctrl-C is seen between two)
            rclpy.spin_once(node, timeout_sec=0.1)
        if not future.done():
            log.error(f"Failed to call service ros_tutorial_srv: no answer within {timeout:g} s")
            return 1
        response = future.result()  # read the response
        log.info(f"send srv, srv.Request.a and b: {request.a}, {request.b}")
        log.info(f"receive srv, srv.Response.result: {response.result}")
        return 0
    except KeyboardInterrupt:
        print("service_client: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    sys.exit(main())
