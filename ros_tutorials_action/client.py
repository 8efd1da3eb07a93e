"""Action client (book: ros_tutorials_action/action_client).

Sends one Fibonacci goal to ``ros_tutorial_action``, logs each feedback, the result and the
final state. Exit status: 0 succeeded; 1 no server within --timeout, rejected, aborted,
canceled, server gone, or no result within --result-timeout (the goal is then canceled);
2 bad arguments; 130 Ctrl-C, after canceling the goal (waiting up to 5 s for each answer).

    action_client [ORDER]   (or: python -m ros_tutorials_action.client [ORDER])
"""

import argparse
import contextlib
import sys
import time

import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from ros_tutorials_interfaces.action import Fibonacci

from ros_tutorials_common.cli import EXIT_INTERRUPTED, positive_seconds, signed_int
from ros_tutorials_common.ros import ros_args, user_args

ACTION_NAME = "ros_tutorial_action"
STATES = {GoalStatus.STATUS_SUCCEEDED: "SUCCEEDED", GoalStatus.STATUS_CANCELED: "CANCELED"}


class FibonacciActionClient(Node):
    def __init__(self) -> None:
        super().__init__("action_client", enable_logger_service=True)
        self.client = ActionClient(self, Fibonacci, ACTION_NAME)  # create the action client
        self.goal_future = None

    def on_feedback(self, msg: Fibonacci.Impl.FeedbackMessage) -> None:  # feedback callback
        self.get_logger().info(f"Received feedback: {list(msg.feedback.sequence)}")

    def wait(self, future, timeout: float) -> bool:
        """Spin until the future is done (True), or timeout s pass or the server goes (False);
        in short slices, so that Ctrl-C is seen between two."""
        end = time.monotonic() + timeout
        while not future.done() and time.monotonic() < end and self.client.server_is_ready():
            rclpy.spin_once(self, timeout_sec=0.1)
        return future.done()

    def finish(self, result_future) -> int:
        status, result = result_future.result().status, result_future.result().result
        self.get_logger().info(f"Result: {list(result.sequence)}")
        self.get_logger().info(f"Action finished: {STATES.get(status, 'ABORTED')}")
        return 0 if status == GoalStatus.STATUS_SUCCEEDED else 1

    def send_goal(self, order: int, timeout: float, result_timeout: float) -> int:
        log = self.get_logger()
        log.info("Waiting for action server to start.")
        if not self.client.wait_for_server(timeout_sec=timeout):  # wait for the server
            log.error(f"Action server {ACTION_NAME} not available after {timeout:g} s")
            return 1
        log.info("Action server started, sending goal.")
        self.goal_future = self.client.send_goal_async(  # send the goal
            Fibonacci.Goal(order=order), feedback_callback=self.on_feedback
        )
        if not self.wait(self.goal_future, timeout):
            log.error(f"No answer from action server {ACTION_NAME} to the goal")
            return 1
        if not self.goal_future.result().accepted:
            log.error(f"Goal of order {order} rejected (the server's log says why)")
            return 1
        result_future = self.goal_future.result().get_result_async()  # ask for the result
        if self.wait(result_future, result_timeout):  # and wait for it
            return self.finish(result_future)
        if not self.client.server_is_ready():
            log.error(f"Action server {ACTION_NAME} went away before the goal finished")
            return 1
        log.warning("Action did not finish before the time out.")
        self.cancel()
        return 1

    def cancel(self, timeout: float = 5.0) -> None:
        """Cancel the goal sent, if the server accepted it, and log how it ended."""
        if self.goal_future and self.wait(self.goal_future, timeout):
            goal = self.goal_future.result()
            if goal.accepted:
                self.get_logger().info("Canceling goal")
                canceled, result = goal.cancel_goal_async(), goal.get_result_async()
                if self.wait(canceled, timeout) and self.wait(result, timeout):
                    self.finish(result)


def parse_args(args: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="action_client", description="Send one Fibonacci goal.")
    parser.add_argument("order", metavar="ORDER", nargs="?", type=signed_int(32), default=20,
                        help="how many terms to add to the seeds 0, 1 (default 20)")  # fmt: skip
    parser.add_argument("--timeout", metavar="SECONDS", type=positive_seconds, default=10.0,
                        help="how long to wait for the server (default 10)")  # fmt: skip
    parser.add_argument("--result-timeout", metavar="SECONDS", type=positive_seconds, default=30.0,
                        help="how long to wait for the result (default 30)")  # fmt: skip
    return parser.parse_args(args)


def main(args=None) -> int:
    options = parse_args(user_args(args))  # bad arguments: usage and exit status 2
    # Ctrl-C raises KeyboardInterrupt, and ROS stays up, so that the goal can still be canceled.
    rclpy.init(args=ros_args(args), signal_handler_options=SignalHandlerOptions.NO)
    node = FibonacciActionClient()  # create the node
    try:
        return node.send_goal(options.order, options.timeout, options.result_timeout)
    except KeyboardInterrupt:
        with contextlib.suppress(KeyboardInterrupt):  # a second Ctrl-C: leave at once
            node.cancel()
        return EXIT_INTERRUPTED
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    sys.exit(main())
