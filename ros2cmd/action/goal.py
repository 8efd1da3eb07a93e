"""Waiting on an action goal without hanging, and canceling it on Ctrl-C.

Used by ``ros2 action send_goal``. A goal may run for long, so its waits
(``wait.spin_until``) stop at once on a Ctrl-C noted by ``CtrlC`` (``Interrupted``) and when
the action server goes away (``ServerLost``).

After Ctrl-C, ``cancel_goal`` asks the server to cancel the goal and waits a bounded time for
the answer. That needs ROS still running, so the program must not let rclpy shut ROS down on
SIGINT: it initialises with ``signal_handler_options`` NO (or SIGTERM) and installs ``CtrlC``::

    ctrl_c = CtrlC()
    signal.signal(signal.SIGINT, ctrl_c)
    spin_until(executor, future.done, 30.0, client=client, interrupted=ctrl_c.is_pressed)
"""

from __future__ import annotations

import time
from collections.abc import Callable
from types import FrameType
from typing import TYPE_CHECKING, Any

from ros2cmd.wait import ServerLost, spin_until

if TYPE_CHECKING:
    from rclpy.action import ActionClient
    from rclpy.executors import Executor
    from rclpy.task import Future

CANCEL_TIMEOUT = 5.0


class CtrlC:
    """A SIGINT handler that only notes the Ctrl-C: the goal is canceled from the main loop,
    between two spins. A second Ctrl-C means "leave now" and raises KeyboardInterrupt."""

    def __init__(self) -> None:
        self.pressed = False

    def __call__(self, signum: int, frame: FrameType | None) -> None:
        if self.pressed:
            raise KeyboardInterrupt
        self.pressed = True

    def is_pressed(self) -> bool:
        return self.pressed


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
    answer in time. Not interruptible: a second Ctrl-C raises KeyboardInterrupt (see CtrlC).
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
