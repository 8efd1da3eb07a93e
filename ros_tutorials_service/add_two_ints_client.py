"""AddTwoInts client (the classic rospy/roscpp tutorial of seeds 001-004).

Asks ``add_two_ints`` for X + Y once and logs "Sum: ...".

    add_two_ints_client 1 2   (or: python -m ros_tutorials_service.add_two_ints_client 1 2)

Exit status: 0 answered; 1 no server, or no answer, within --timeout seconds (default 5);
2 usage error (not two int64 integers); 130 Ctrl-C.
"""

import argparse
import sys
import time

import rclpy
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from ros_tutorials_interfaces.srv import AddTwoInts

from ros_tutorials_common.cli import EXIT_INTERRUPTED, positive_seconds, signed_int
from ros_tutorials_common.ros import ros_args, user_args


def parse_args(args: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="add_two_ints_client", description="Add X and Y once.")
    parser.add_argument("x", metavar="X", type=signed_int(64), help="first operand (int64)")
    parser.add_argument("y", metavar="Y", type=signed_int(64), help="second operand (int64)")
    parser.add_argument(
        "--timeout", metavar="SECONDS", type=positive_seconds, default=5.0,
        help="how long to wait for the server, then for its answer (default 5)",
    )  # fmt: skip
    return parser.parse_args(args)


def main(args=None) -> int:
    options = parse_args(user_args(args))  # bad arguments: usage and exit status 2
    # Ctrl-C raises KeyboardInterrupt below, and ROS stays up until we shut it down.
    rclpy.init(args=ros_args(args), signal_handler_options=SignalHandlerOptions.NO)
    node = Node("add_two_ints_client", enable_logger_service=True)
    client = node.create_client(AddTwoInts, "add_two_ints")
    log, timeout = node.get_logger(), options.timeout
    try:
        if not client.wait_for_service(timeout_sec=min(1.0, timeout)):
            log.info(f"waiting for service add_two_ints (up to {timeout:g} s)...")
            if not client.wait_for_service(timeout_sec=timeout - 1.0):
                log.error(f"Failed to call service add_two_ints: no server within {timeout:g} s")
                return 1
        future = client.call_async(AddTwoInts.Request(a=options.x, b=options.y))
        end = time.monotonic() + timeout  # wait for the answer, spinning in short slices
        while not future.done() and time.monotonic() < end:  # (Ctrl-C is seen between two)
            rclpy.spin_once(node, timeout_sec=0.1)
        if not future.done():
            log.error(f"Failed to call service add_two_ints: no answer within {timeout:g} s")
            return 1
        log.info(f"Sum: {future.result().sum}")
        return 0
    except KeyboardInterrupt:
        print("add_two_ints_client: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    sys.exit(main())
