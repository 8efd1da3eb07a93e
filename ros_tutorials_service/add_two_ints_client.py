"""AddTwoInts client (the classic rospy/roscpp tutorial of seeds 001-004): asks
``add_two_ints`` for X + Y once and logs "Sum: ...".

    add_two_ints_client 1 2   (or: python -m ros_tutorials_service.add_two_ints_client 1 2)
"""

import sys

import rclpy
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from ros_tutorials_interfaces.srv import AddTwoInts

from ros_tutorials_common.ros import service_client_steps as steps


def main(args=None) -> int:
    options = steps.parse_args(args, "add_two_ints_client", "X", "Y")  # else usage, exit status 2
    rclpy.init(args=steps.ros_args(args), signal_handler_options=SignalHandlerOptions.NO)
    node = Node("add_two_ints_client", enable_logger_service=True)
    client = node.create_client(AddTwoInts, "add_two_ints")
    try:
        if not steps.wait_for_service(node, client, options.timeout):
            return 1
        future = client.call_async(AddTwoInts.Request(a=options.x, b=options.y))
        if not steps.wait_for_answer(node, client, future, options.timeout):
            return 1
        node.get_logger().info(f"Sum: {future.result().sum}")
        return 0
    except KeyboardInterrupt:
        return steps.interrupted("add_two_ints_client")  # Ctrl-C: exit status 130
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    sys.exit(main())
