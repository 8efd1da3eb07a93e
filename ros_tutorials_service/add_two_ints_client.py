"""AddTwoInts client (the classic rospy/roscpp tutorial of seeds 001-004): asks
``add_two_ints`` for X + Y once and logs "Sum: ...".

    add_two_ints_client 1 2   (or: python -m ros_tutorials_service.add_two_ints_client 1 2)
"""

import argparse
import re
import sys

import rclpy
from rclpy.node import Node
from rclpy.utilities import remove_ros_args
from ros_tutorials_interfaces.srv import AddTwoInts


def int64(text: str) -> int:
    """An argparse type: a whole number as the seed's atoll reads it (digits, a sign), in int64."""
    if not re.fullmatch(r"[+-]?[0-9]+", text):
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer")
    if not -(2**63) <= int(text) < 2**63:
        raise argparse.ArgumentTypeError(f"{text} does not fit in a 64-bit integer")
    return int(text)


def main(args: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="add_two_ints_client")  # else usage, exit status 2
    parser.add_argument("x", metavar="X", type=int64)
    parser.add_argument("y", metavar="Y", type=int64)
    parser.add_argument("--timeout", metavar="SECONDS", type=float, default=5.0)
    options = parser.parse_args(remove_ros_args(args or sys.argv)[1:])
    timeout = options.timeout
    if not 0 < timeout <= 1e6:  # nan and inf too: rcl counts a wait in int64 nanoseconds
        parser.error(f"--timeout: {timeout:g} is not a positive number of seconds up to 1e6")

    rclpy.init(args=args)
    node = Node("add_two_ints_client", enable_logger_service=True)
    client = node.create_client(AddTwoInts, "add_two_ints")
    log = node.get_logger()
    try:
        if not client.wait_for_service(timeout_sec=timeout):
            log.error(f"Failed to call service {client.srv_name}: no server within {timeout:g} s")
            return 1
        future = client.call_async(AddTwoInts.Request(a=options.x, b=options.y))
        rclpy.spin_until_future_complete(node, future, timeout_sec=timeout)
        if not future.done():
            log.error(f"Failed to call service {client.srv_name}: no answer within {timeout:g} s")
            return 1
        log.info(f"Sum: {future.result().sum}")
        return 0
    except KeyboardInterrupt:
        return 130  # Ctrl-C: the exit status a shell gives a command it interrupted
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    sys.exit(main())
