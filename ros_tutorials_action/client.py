"""Action client (book: ros_tutorials_action/action_client): sends one Fibonacci goal to
``ros_tutorial_action``, logs each feedback, the result and the final state, and exits.

    action_client 5        (or: python -m ros_tutorials_action.client 5; ORDER is 20 if not given)
"""

import argparse
import sys

import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.utilities import remove_ros_args
from ros_tutorials_interfaces.action import Fibonacci

ACTION_NAME = "ros_tutorial_action"
STATES = {
    GoalStatus.STATUS_SUCCEEDED: "SUCCEEDED",
    GoalStatus.STATUS_CANCELED: "CANCELED",
    GoalStatus.STATUS_ABORTED: "ABORTED",
}


def main(args: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="action_client")  # else usage, exit status 2
    parser.add_argument("order", metavar="ORDER", type=int, nargs="?", default=20)
    parser.add_argument("--timeout", metavar="SECONDS", type=float, default=30.0)
    options = parser.parse_args(remove_ros_args(args or sys.argv)[1:])
    if not -(2**31) <= options.order < 2**31 or not 0 < options.timeout <= 3600:
        parser.error("ORDER must fit in int32, --timeout be in (0, 3600] s")  # else a traceback

    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = Node("action_client")  # create the node
    client = ActionClient(node, Fibonacci, ACTION_NAME)  # and the action client
    log = node.get_logger()
    try:
        log.info("Waiting for action server to start.")
        if not client.wait_for_server(timeout_sec=options.timeout):  # wait for the server
            log.error(f"Action server {ACTION_NAME} not available after {options.timeout:g} s")
            return 1
        log.info("Action server started, sending goal.")  # the goal, and the feedback callback
        sent = client.send_goal_async(
            Fibonacci.Goal(order=options.order),
            lambda msg: log.info(f"Received feedback: {list(msg.feedback.sequence)}"),
        )
        rclpy.spin_until_future_complete(node, sent, timeout_sec=options.timeout)
        if not sent.done():
            log.error(f"No answer from action server {ACTION_NAME} to the goal")
            return 1
        if not sent.result().accepted:
            log.error(f"Goal of order {options.order} rejected (the server's log says why)")
            return 1
        result = sent.result().get_result_async()  # ask for the result, wait for it (30 s)
        rclpy.spin_until_future_complete(node, result, timeout_sec=options.timeout)
        if not result.done():
            log.warning("Action did not finish before the time out.")
            return 1
        log.info(f"Result: {list(result.result().result.sequence)}")
        log.info(f"Action finished: {STATES.get(result.result().status, 'UNKNOWN')}")
        return 0 if result.result().status == GoalStatus.STATUS_SUCCEEDED else 1
    except (KeyboardInterrupt, ExternalShutdownException):
        return 130  # Ctrl-C: the exit status a shell gives a command it interrupted
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    sys.exit(main())
