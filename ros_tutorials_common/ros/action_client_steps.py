"""What the action lesson's client does besides the book's steps; a learner can skip this.

The book's client waits for the server, sends a goal and waits up to 30 s for the result. A
command line has to do more: refuse bad arguments with a usage line (exit status 2), bound
every wait and say which one failed, notice a server that went away, and cancel its goal on
Ctrl-C or when the result does not come in time. Those parts live here, so that the lesson
file shows the book's steps (``wait_for_server``, ``send_goal_async`` with a feedback callback,
``get_result_async``, the final state)::

    waits = GoalWaits(node, client, "ros_tutorial_action")
    goal_future = client.send_goal_async(goal, feedback_callback=...)
    goal_handle = waits.accepted(goal_future, goal, options.timeout)   # None: said why not
    result_future = goal_handle.get_result_async()
    if waits.done(result_future, options.result_timeout): ...
"""

from __future__ import annotations

import argparse
import contextlib
import time
from collections.abc import Callable, Sequence
from typing import Any

import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient
from rclpy.action.client import ClientGoalHandle
from rclpy.node import Node
from rclpy.task import Future

from ros_tutorials_common.cli import EXIT_INTERRUPTED, positive_seconds, signed_int
from ros_tutorials_common.ros.node_main import ros_args, user_args

__all__ = ["EXIT_INTERRUPTED", "GoalWaits", "parse_args", "ros_args", "state_name"]
SPIN_SLICE = 0.1  # seconds: how long one spin may block, so that Ctrl-C is seen in between
CANCEL_TIMEOUT = 5.0  # seconds to wait for the answer to a cancel, then for the result
STATE_NAMES = {
    GoalStatus.STATUS_SUCCEEDED: "SUCCEEDED",
    GoalStatus.STATUS_CANCELED: "CANCELED",
    GoalStatus.STATUS_ABORTED: "ABORTED",
}


def parse_args(args: Sequence[str] | None = None) -> argparse.Namespace:
    """The client's command line (sys.argv unless args, without the ROS arguments): ORDER
    (int32, default 20 as in the book), --timeout and --result-timeout. Anything else prints
    the usage and ends the program with exit status 2."""
    parser = argparse.ArgumentParser(
        prog="action_client",
        description="Send one Fibonacci goal, log its feedback, result and final state.",
        epilog="exit status: 0 succeeded; 1 no server within --timeout, rejected, aborted, "
        "canceled, server gone, or no result within --result-timeout (the goal is then "
        "canceled); 2 usage error; 130 Ctrl-C, after canceling the goal",
    )
    parser.add_argument("order", metavar="ORDER", nargs="?", type=signed_int(32), default=20,
                        help="how many terms to add to the seeds 0, 1 (default 20)")  # fmt: skip
    parser.add_argument("--timeout", metavar="SECONDS", type=positive_seconds, default=10.0,
                        help="how long to wait for the server (default 10)")  # fmt: skip
    parser.add_argument("--result-timeout", metavar="SECONDS", type=positive_seconds, default=30.0,
                        help="how long to wait for the result (default 30)")  # fmt: skip
    return parser.parse_args(user_args(args))


def state_name(status: int) -> str:
    """A goal's final state as the book's ``state.toString()`` names it."""
    return STATE_NAMES.get(status, f"UNKNOWN ({status})")


class GoalWaits:
    """Bounded waits for one goal of an action client. Each spins the node in short slices (so
    Ctrl-C is seen between two) and ends early if the action server goes away; a wait that
    fails logs one line saying which. ``cancel`` cancels the goal, if one was accepted."""

    def __init__(self, node: Node, client: ActionClient, name: str) -> None:
        self.node, self.client, self.name = node, client, name
        self.goal_future: Future | None = None

    def done(self, future: Future, timeout: float) -> bool:
        """Spin until the future is done (True), or ``timeout`` s pass, or the server goes."""
        end = time.monotonic() + timeout
        while not future.done() and time.monotonic() < end and self.client.server_is_ready():
            rclpy.spin_once(self.node, timeout_sec=SPIN_SLICE)
        return future.done()

    def accepted(self, goal_future: Future, goal: Any, timeout: float) -> ClientGoalHandle | None:
        """The goal's handle once the server accepted it; None (and one line) if the server
        rejected it or did not answer within ``timeout`` seconds. From now on, ``cancel``
        cancels the goal."""
        self.goal_future = goal_future
        if not self.done(goal_future, timeout):
            self.node.get_logger().error(f"No answer from action server {self.name} to the goal")
            return None
        if not goal_future.result().accepted:
            self.node.get_logger().error(
                f"Goal of order {goal.order} rejected (the server's log says why)"
            )
            return None
        return goal_future.result()

    def server_gone(self) -> bool:
        """True (and one line) if the action server went away: the goal cannot finish."""
        if self.client.server_is_ready():
            return False
        self.node.get_logger().error(
            f"Action server {self.name} went away before the goal finished"
        )
        return True

    def cancel(self, on_result: Callable[[object], object]) -> None:
        """Cancel the goal sent, if the server accepted it, and hand its result to on_result.
        Each answer is awaited at most CANCEL_TIMEOUT seconds; a second Ctrl-C gives up."""
        with contextlib.suppress(KeyboardInterrupt):
            if self.goal_future and self.done(self.goal_future, CANCEL_TIMEOUT):
                goal_handle = self.goal_future.result()
                if goal_handle.accepted:
                    self.node.get_logger().info("Canceling goal")
                    canceled = goal_handle.cancel_goal_async()
                    result = goal_handle.get_result_async()
                    if self.done(canceled, CANCEL_TIMEOUT) and self.done(result, CANCEL_TIMEOUT):
                        on_result(result.result())
