"""Action client (book: ros_tutorials_action/action_client).

Sends one Fibonacci goal to the action ``ros_tutorial_action`` (order 20 unless given, as in
the book), logs each feedback, then the result and the final status of the goal.

    python -m ros_tutorials_action.client [ORDER]     (or: action_client [ORDER])
    action_client 5 --timeout 3 --result-timeout 60

Exit status: 0 the goal succeeded; 1 no action server within --timeout, goal rejected,
aborted or canceled, or no result within --result-timeout (the goal is then canceled);
2 bad arguments; 130 Ctrl-C, after the running goal has been canceled on the server (the
client waits up to 5 s, action_goal.CANCEL_TIMEOUT, for the server to confirm).
"""

from __future__ import annotations

import argparse
import signal
import sys
from collections.abc import Sequence
from typing import Any

import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient
from rclpy.executors import Executor, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from rclpy.task import Future
from ros_tutorials_interfaces.action import Fibonacci

from ros_tutorials_action.server import ACTION_NAME
from ros_tutorials_common.action_goal import (
    CtrlC,
    Interrupted,
    ServerLost,
    cancel_goal,
    spin_until,
)
from ros_tutorials_common.cli import EXIT_INTERRUPTED, positive_seconds, signed_int
from ros_tutorials_common.node_main import init, user_args

DEFAULT_ORDER = 20
STATUS_NAMES = {
    GoalStatus.STATUS_SUCCEEDED: "SUCCEEDED",
    GoalStatus.STATUS_CANCELED: "CANCELED",
    GoalStatus.STATUS_ABORTED: "ABORTED",
}


class FibonacciActionClient(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("action_client", enable_logger_service=True, **node_kwargs)
        self.client = ActionClient(self, Fibonacci, ACTION_NAME)
        # The SIGINT handler (installed by main): Ctrl-C only sets a flag that the waits in
        # run() check, so that the goal can still be canceled through ROS.
        self.ctrl_c = CtrlC()
        self.goal_future: Future | None = None
        self.result_future: Future | None = None

    def on_feedback(self, feedback_msg: Fibonacci.Impl.FeedbackMessage) -> None:
        self.get_logger().info(f"Received feedback: {list(feedback_msg.feedback.sequence)}")

    def run(
        self, executor: Executor, order: int, server_timeout: float, result_timeout: float
    ) -> int:
        """Send one goal and wait for its result; Ctrl-C cancels it. Returns the exit code."""
        log = self.get_logger()
        log.info("Waiting for action server to start.")
        # Every wait notices Ctrl-C; those after the goal is sent also notice a vanished server.
        interrupted = self.ctrl_c.is_pressed
        try:
            if not spin_until(
                executor, self.client.server_is_ready, server_timeout, interrupted=interrupted
            ):
                log.error(f"Action server {ACTION_NAME} not available after {server_timeout:g} s")
                return 1
            log.info("Action server started, sending goal.")
            self.goal_future = self.client.send_goal_async(
                Fibonacci.Goal(order=order), feedback_callback=self.on_feedback
            )
            if not spin_until(
                executor,
                self.goal_future.done,
                server_timeout,
                client=self.client,
                interrupted=interrupted,
            ):
                log.error(f"No answer from action server {ACTION_NAME} to the goal")
                return 1
            goal_handle = self.goal_future.result()
            if not goal_handle.accepted:
                log.error(f"Goal of order {order} rejected (the server's log says why)")
                return 1
            self.result_future = goal_handle.get_result_async()
            if not spin_until(
                executor,
                self.result_future.done,
                result_timeout,
                client=self.client,
                interrupted=interrupted,
            ):
                log.warning("Action did not finish before the time out.")
                self.cancel(executor)
                return 1
        except Interrupted:
            self.cancel(executor)
            return EXIT_INTERRUPTED
        except ServerLost:
            log.error(f"Action server {ACTION_NAME} went away before the goal finished")
            return 1
        return self.report(self.result_future.result())

    def report(self, response: Any) -> int:
        """Log a GetResult response (result and final status); the exit code it deserves."""
        log = self.get_logger()
        log.info(f"Result: {list(response.result.sequence)}")
        log.info(f"Action finished: {STATUS_NAMES.get(response.status, response.status)}")
        return 0 if response.status == GoalStatus.STATUS_SUCCEEDED else 1

    def cancel(self, executor: Executor) -> None:
        """Cancel the goal sent, if the server took it; wait a bounded time (CANCEL_TIMEOUT)."""
        response = cancel_goal(
            executor, self.client, self.goal_future, self.result_future, self.get_logger()
        )
        if response is not None:
            self.report(response)


def parse_args(args: Sequence[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="action_client",
        description=f"Send one Fibonacci goal to the action {ACTION_NAME} and wait for it.",
    )
    parser.add_argument(
        "order",
        metavar="ORDER",
        nargs="?",
        type=signed_int(32),
        default=DEFAULT_ORDER,
        help=f"how many terms to append to the seeds 0, 1 (default {DEFAULT_ORDER})",
    )
    parser.add_argument(
        "--timeout",
        type=positive_seconds,
        default=10.0,
        metavar="SECONDS",
        help="how long to wait for the action server (default 10)",
    )
    parser.add_argument(
        "--result-timeout",
        type=positive_seconds,
        default=30.0,
        metavar="SECONDS",
        help="how long to wait for the result before canceling the goal (default 30, the book's)",
    )
    return parser.parse_args(args)


def main(argv: Sequence[str] | None = None) -> int:
    argv = sys.argv if argv is None else argv
    args = parse_args(user_args(argv))  # bad arguments: usage message, exit 2
    # rclpy's own Ctrl-C handler would shut ROS down at once, but this client still needs ROS
    # after Ctrl-C to cancel its goal: it handles SIGINT itself (FibonacciActionClient.ctrl_c).
    init(argv, signal_handler_options=SignalHandlerOptions.NO)
    node = None
    executor = SingleThreadedExecutor()
    try:
        node = FibonacciActionClient()
        signal.signal(signal.SIGINT, node.ctrl_c)
        executor.add_node(node)
        return node.run(executor, args.order, args.timeout, args.result_timeout)
    except KeyboardInterrupt:  # a second Ctrl-C while canceling
        return EXIT_INTERRUPTED
    finally:
        if node is not None:
            node.destroy_node()
        executor.shutdown()
        rclpy.try_shutdown()


if __name__ == "__main__":
    raise SystemExit(main())
