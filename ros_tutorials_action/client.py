"""Action client (book: ros_tutorials_action/action_client).

Sends one Fibonacci goal to the action ``ros_tutorial_action`` (order 20 unless given, as in
the book), logs each feedback, then the result and the final status of the goal.

    python -m ros_tutorials_action.client [ORDER]     (or: action_client [ORDER])
    action_client 5 --timeout 3 --result-timeout 60

Exit status: 0 the goal succeeded; 1 no action server within --timeout, goal rejected,
aborted or canceled, or no result within --result-timeout (the goal is then canceled);
2 bad arguments; 130 Ctrl-C, after the running goal has been canceled on the server (the
client waits up to CANCEL_TIMEOUT seconds for the server to confirm).
"""

from __future__ import annotations

import argparse
import signal
import sys
import time
from collections.abc import Callable, Sequence
from types import FrameType
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
from ros_tutorials_common.cli import EXIT_INTERRUPTED, positive_seconds, signed_int
from ros_tutorials_common.node_main import init, user_args

DEFAULT_ORDER = 20
CANCEL_TIMEOUT = 5.0
# Waits spin in slices this long, so that a Ctrl-C is noticed at once (see on_sigint) ...
SPIN_SLICE = 0.1
# ... and check this often that the action server is still there (it may crash or be stopped).
SERVER_CHECK_PERIOD = 1.0
STATUS_NAMES = {
    GoalStatus.STATUS_SUCCEEDED: "SUCCEEDED",
    GoalStatus.STATUS_CANCELED: "CANCELED",
    GoalStatus.STATUS_ABORTED: "ABORTED",
}


class Interrupted(Exception):
    """The user pressed Ctrl-C."""


class ServerLost(Exception):
    """The action server went away while we waited for it to answer."""


class FibonacciActionClient(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("action_client", **node_kwargs)
        self.client = ActionClient(self, Fibonacci, ACTION_NAME)
        self.interrupted = False
        self.goal_future: Future | None = None
        self.result_future: Future | None = None

    def on_sigint(self, signum: int, frame: FrameType | None) -> None:
        # Only note it: the goal is canceled from the main loop, between two spins. A second
        # Ctrl-C means "leave now".
        if self.interrupted:
            raise KeyboardInterrupt
        self.interrupted = True

    def on_feedback(self, feedback_msg: Fibonacci.Impl.FeedbackMessage) -> None:
        self.get_logger().info(f"Received feedback: {list(feedback_msg.feedback.sequence)}")

    def run(
        self, executor: Executor, order: int, server_timeout: float, result_timeout: float
    ) -> int:
        """Send one goal and wait for its result; Ctrl-C cancels it. Returns the exit code."""
        log = self.get_logger()
        log.info("Waiting for action server to start.")
        try:
            if not self.spin_until(executor, self.client.server_is_ready, server_timeout):
                log.error(f"Action server {ACTION_NAME} not available after {server_timeout:g} s")
                return 1
            log.info("Action server started, sending goal.")
            self.goal_future = self.client.send_goal_async(
                Fibonacci.Goal(order=order), feedback_callback=self.on_feedback
            )
            if not self.spin_until(
                executor, self.goal_future.done, server_timeout, server_needed=True
            ):
                log.error(f"No answer from action server {ACTION_NAME} to the goal")
                return 1
            goal_handle = self.goal_future.result()
            if not goal_handle.accepted:
                log.error(f"Goal of order {order} rejected (the server's log says why)")
                return 1
            self.result_future = goal_handle.get_result_async()
            if not self.spin_until(
                executor, self.result_future.done, result_timeout, server_needed=True
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

    def spin_until(
        self,
        executor: Executor,
        done: Callable[[], bool],
        timeout: float,
        *,
        server_needed: bool = False,
        interruptible: bool = True,
    ) -> bool:
        """Spin until done() (True) or timeout seconds pass (False).

        Raises Interrupted on Ctrl-C if interruptible, and ServerLost if server_needed and the
        server goes away.
        """
        deadline = time.monotonic() + timeout
        next_check = time.monotonic() + SERVER_CHECK_PERIOD
        while not done():
            if interruptible and self.interrupted:
                raise Interrupted
            now = time.monotonic()
            if now >= deadline:
                return False
            if server_needed and now >= next_check:
                if not self.client.server_is_ready():
                    raise ServerLost
                next_check = now + SERVER_CHECK_PERIOD
            executor.spin_once(timeout_sec=min(SPIN_SLICE, deadline - now))
        return True

    def report(self, response: Any) -> int:
        """Log a GetResult response (result and final status); the exit code it deserves."""
        log = self.get_logger()
        log.info(f"Result: {list(response.result.sequence)}")
        log.info(f"Action finished: {STATUS_NAMES.get(response.status, response.status)}")
        return 0 if response.status == GoalStatus.STATUS_SUCCEEDED else 1

    def cancel(self, executor: Executor) -> None:
        """Cancel the goal sent, if the server took it; wait at most CANCEL_TIMEOUT seconds."""
        log = self.get_logger()
        deadline = time.monotonic() + CANCEL_TIMEOUT

        def wait(future: Future) -> Any | None:
            remaining = max(0.0, deadline - time.monotonic())
            # Not interruptible: a second Ctrl-C raises KeyboardInterrupt (see on_sigint).
            try:
                finished = self.spin_until(
                    executor, future.done, remaining, server_needed=True, interruptible=False
                )
            except ServerLost:
                return None
            return future.result() if finished else None

        # The goal may still be on its way: the server could accept it after we leave.
        goal_handle = wait(self.goal_future) if self.goal_future else None
        if goal_handle is None or not goal_handle.accepted:
            return
        log.info("Canceling goal")
        response = wait(goal_handle.cancel_goal_async())
        if response is None:
            log.error(f"No answer to the cancel request within {CANCEL_TIMEOUT:g} s")
            return
        if not response.goals_canceling:
            log.warning("The server did not cancel the goal (it had already finished)")
        if self.result_future is None:
            self.result_future = goal_handle.get_result_async()
        result = wait(self.result_future)
        if result is not None:
            self.report(result)


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
    # after Ctrl-C to cancel its goal: it handles SIGINT itself (FibonacciActionClient.on_sigint).
    init(argv, signal_handler_options=SignalHandlerOptions.NO)
    node = None
    executor = SingleThreadedExecutor()
    try:
        node = FibonacciActionClient()
        signal.signal(signal.SIGINT, node.on_sigint)
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
