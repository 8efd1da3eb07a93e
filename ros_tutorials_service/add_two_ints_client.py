"""Seed 002's add_two_ints_client.cpp: asks ``add_two_ints`` for X + Y once, logs "Sum: ..."."""

import argparse
import sys

import rclpy
from rclpy.node import Node
from rclpy.utilities import remove_ros_args
from ros_tutorials_interfaces.srv import AddTwoInts


def main(args: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="add_two_ints_client")  # else usage, exit status 2
    parser.add_argument("x", metavar="X", type=int)
    parser.add_argument("y", metavar="Y", type=int)
    parser.add_argument("--timeout", metavar="SECONDS", type=float, default=5.0)
    options = parser.parse_args(remove_ros_args(args or sys.argv)[1:])
    if not all(-(2**63) <= n < 2**63 for n in (options.x, options.y)):
        parser.error("X and Y must fit in int64")  # else rclpy fails with a SystemError
    if not 0 < options.timeout <= 3600:  # rclpy needs a finite wait
        parser.error("--timeout must be more than 0 and at most 3600 seconds")

    rclpy.init(args=args)
    node = Node("add_two_ints_client")
    client = node.create_client(AddTwoInts, "add_two_ints")
    try:  # wait for the service, call it, wait for the answer: --timeout seconds per wait
        if client.wait_for_service(timeout_sec=options.timeout):
            future = client.call_async(AddTwoInts.Request(a=options.x, b=options.y))
            rclpy.spin_until_future_complete(node, future, timeout_sec=options.timeout)
            if future.done():
                node.get_logger().info(f"Sum: {future.result().sum}")
                return 0
        failed = "no answer" if client.service_is_ready() else "no server"
        node.get_logger().error(  # the seed's else
            f"Failed to call service add_two_ints: {failed} within {options.timeout:g} s"
        )
        return 1
    except KeyboardInterrupt:
        return 130  # Ctrl-C: the exit status a shell gives a command it interrupted
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    sys.exit(main())
