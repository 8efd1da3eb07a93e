"""Seed 002's add_two_ints_client.cpp: asks ``add_two_ints`` for X + Y once, logs "Sum: ..."."""

import argparse
import re
import sys

import rclpy
from rclpy.node import Node
from rclpy.utilities import remove_ros_args
from ros_tutorials_interfaces.srv import AddTwoInts


def int64(text: str) -> int:  # an argparse type: digits and a sign, as the seed's atol reads them
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
    try:  # wait for the service, call it, wait for the answer: --timeout seconds per wait
        if client.wait_for_service(timeout_sec=timeout):
            future = client.call_async(AddTwoInts.Request(a=options.x, b=options.y))
            rclpy.spin_until_future_complete(node, future, timeout_sec=timeout)
            if future.done():
                node.get_logger().info(f"Sum: {future.result().sum}")
                return 0
        failed = f"no {'answer' if client.service_is_ready() else 'server'} within {timeout:g} s"
        node.get_logger().error(f"Failed to call service add_two_ints: {failed}")  # the seed's else
        return 1
    except KeyboardInterrupt:
        return 130  # Ctrl-C: the exit status a shell gives a command it interrupted
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    sys.exit(main())
