"""Action client (book: ros_tutorials_action/action_client): sends one Fibonacci goal to
``ros_tutorial_action``, logs each feedback, the result and the final state, and exits.

    action_client [ORDER]   (or: python -m ros_tutorials_action.client [ORDER]; --help)
"""

import argparse
import sys
import time

import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from rclpy.task import Future
from rclpy.utilities import remove_ros_args
from ros_tutorials_interfaces.action import Fibonacci

ACTION_NAME = "ros_tutorial_action"
STATES = {4: "SUCCEEDED", 5: "CANCELED", 6: "ABORTED"}  # a goal's final GoalStatus, by name


def wait(node: Node, client: ActionClient, future: Future, timeout: float) -> bool:
    """Spin until the future is done (True), or timeout seconds pass, or the server goes away;
    in short spins, so that Python sees a Ctrl-C between two."""
    end = time.monotonic() + timeout
    while not future.done() and time.monotonic() < end and client.server_is_ready():
        rclpy.spin_once(node, timeout_sec=0.1)
    return future.done()


def main(args: list[str] | None = None) -> int:
    # The command line, without the ROS arguments; anything else: usage, exit status 2.
    parser = argparse.ArgumentParser(prog="action_client")
    parser.add_argument("order", metavar="ORDER", type=int, nargs="?", default=20)
    parser.add_argument("--timeout", metavar="SECONDS", type=float, default=10.0)
    parser.add_argument("--result-timeout", metavar="SECONDS", type=float, default=30.0)
    options = parser.parse_args(remove_ros_args(args or sys.argv)[1:])
    if not -(2**31) <= options.order < 2**31:
        parser.error(f"ORDER: {options.order} does not fit in a 32-bit integer")
    if not (0 < options.timeout <= 1e6 and 0 < options.result_timeout <= 1e6):  # nan, inf too
        parser.error("--timeout, --result-timeout: a positive number of seconds up to 1e6")

    # Without rclpy's signal handler, Ctrl-C raises KeyboardInterrupt and ROS stays up, so that
    # the goal can still be canceled.
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = Node("action_client", enable_logger_service=True)  # create the node
    client = ActionClient(node, Fibonacci, ACTION_NAME)  # and the action client
    log = node.get_logger()
    goal_future = None

    def on_feedback(msg: Fibonacci.Impl.FeedbackMessage) -> None:  # the feedback callback
        log.info(f"Received feedback: {list(msg.feedback.sequence)}")

    def on_result(result_future: Future) -> int:  # the result and the final state
        response = result_future.result()
        log.info(f"Result: {list(response.result.sequence)}")
        log.info(f"Action finished: {STATES.get(response.status, response.status)}")
        return 0 if response.status == GoalStatus.STATUS_SUCCEEDED else 1

    def cancel() -> None:  # cancel the goal, if the server accepted it; its result, in 5 s
        if goal_future and wait(node, client, goal_future, 5.0) and goal_future.result().accepted:
            log.info("Canceling goal")
            goal_future.result().cancel_goal_async()
            result_future = goal_future.result().get_result_async()
            if wait(node, client, result_future, 5.0):
                on_result(result_future)

    try:
        log.info("Waiting for action server to start.")
        if not client.wait_for_server(timeout_sec=options.timeout):  # wait for the server
            log.error(f"Action server {ACTION_NAME} not available after {options.timeout:g} s")
            return 1
        log.info("Action server started, sending goal.")
        goal = Fibonacci.Goal(order=options.order)  # send the goal, with the feedback callback
        goal_future = client.send_goal_async(goal, feedback_callback=on_feedback)
        if not wait(node, client, goal_future, options.timeout):
            log.error(f"No answer from action server {ACTION_NAME} to the goal")
            return 1
        if not goal_future.result().accepted:
            log.error(f"Goal of order {goal.order} rejected (the server's log says why)")
            return 1
        result_future = goal_future.result().get_result_async()  # ask for the result, wait
        if wait(node, client, result_future, options.result_timeout):
            return on_result(result_future)
        if not client.server_is_ready():
            log.error(f"Action server {ACTION_NAME} went away before the goal finished")
            return 1
        log.warning("Action did not finish before the time out.")  # the book's line
        cancel()
        return 1
    except KeyboardInterrupt:
        cancel()  # Ctrl-C: cancel the goal, then exit status 130 (a shell's for Ctrl-C)
        return 130
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    sys.exit(main())
