"""Waiting on an action goal without hanging, and canceling it on Ctrl-C.

Used by ``ros2 action send_goal``. A goal may run for long, so its waits
(``wait.spin_until``) stop at once on a Ctrl-C noted by ``StopSignals`` (``Interrupted``) and when
the action server goes away (``ServerLost``).

After Ctrl-C, ``cancel_goal`` asks the server to cancel the goal and waits a bounded time for
the answer. That needs ROS still running, so the program must not let rclpy shut ROS down on
SIGINT: it initialises with ``signal_handler_options`` NO (or SIGTERM) and notes Ctrl-C with
ros_tutorials_common/shutdown.py's ``StopSignals`` (a second Ctrl-C: KeyboardInterrupt)::

    ctrl_c = StopSignals((signal.SIGINT,), second_raises=True)
    spin_until(executor, future.done, 30.0, client=client, interrupted=lambda: ctrl_c.received)
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ros_tutorials_common.wait import ServerLost, spin_until

if TYPE_CHECKING:
    from rclpy.action import ActionClient
    from rclpy.executors import Executor
    from rclpy.task import Future

CANCEL_TIMEOUT = 5.0


def cancel_goal(
    executor: Executor,
    client: ActionClient,
    goal_future: Future | None,
    on_canceling: Callable[[], None],
    timeout: float = CANCEL_TIMEOUT,
) -> Any | None:
    """Cancel the goal sent (goal_future), if the server took it; wait at most timeout seconds.

    Calls on_canceling() just before the cancel request goes out (to say so). Returns the
    server's CancelGoal response, or None: the goal was never accepted, or the server did not
    answer in time. Not interruptible: a second Ctrl-C raises KeyboardInterrupt (StopSignals).
    """
    deadline = time.monotonic() + timeout

    def wait(future: Future) -> Any | None:
        remaining = max(0.0, deadline - time.monotonic())
        try:
            finished = spin_until(executor, future.done, remaining, client=client)
        except ServerLost:
            return None
        return future.result() if finished else None

    # The goal may still be on its way: the server could accept it after we leave.
    goal_handle = wait(goal_future) if goal_future is not None else None
    if goal_handle is None or not goal_handle.accepted:
        return None
    on_canceling()
    return wait(goal_handle.cancel_goal_async())
