"""The one wait loop of the tools and the toolkit's nodes (view_frames): spin until something
is true, a bounded time.

``Graph.wait_for`` (a name to appear, a service to answer), ``Graph.settle`` (discovery to
complete) and ``action send_goal`` (a goal's answer) all wait here. A goal may run for long,
so this loop can also:

- stop at once when ``interrupted()`` says Ctrl-C was pressed (``Interrupted``), or when a
  Ctrl-C was counted whose KeyboardInterrupt never reached it (ros_tutorials_common/shutdown.py);
- check every SERVER_CHECK_PERIOD that an action server is still in the graph: a server that
  crashed or was stopped never answers, and waiting for it would last forever (``ServerLost``).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, TypeVar

from ros_tutorials_common import shutdown

if TYPE_CHECKING:
    from rclpy.action import ActionClient
    from rclpy.executors import Executor

# Waits spin in slices this long at most, so that a Ctrl-C is noticed at once ...
SPIN_SLICE = 0.1
# ... and check this often that the action server is still there (it may crash or be stopped).
SERVER_CHECK_PERIOD = 1.0

T = TypeVar("T")


class Interrupted(Exception):
    """The user pressed Ctrl-C."""


class ServerLost(Exception):
    """The action server went away while we waited for it to answer."""


def spin_until(
    executor: Executor,
    condition: Callable[[], T],
    timeout: float = math.inf,
    *,
    client: ActionClient | None = None,
    interrupted: Callable[[], bool] | None = None,
    period: float = SPIN_SLICE,
    slow_down: bool = False,
) -> T | None:
    """Spin until condition() gives something true, and return it; None after timeout seconds.

    Raises Interrupted once interrupted() is true, and ServerLost if a client is given and
    its action server goes away. ``period``: the longest single spin (how often condition()
    is asked when nothing arrives). ``slow_down``: for a condition that only polling sees
    (the graph: nothing wakes the executor when it changes): ask every ``period`` at first,
    then less often, up to every SPIN_SLICE after a second (what usually appears does so
    within a few hundred milliseconds; every look costs CPU).
    """
    start = time.monotonic()
    deadline = start + timeout
    next_check = start + SERVER_CHECK_PERIOD
    presses = shutdown.presses
    while not (result := condition()):
        if shutdown.presses != presses:  # a Ctrl-C came and its KeyboardInterrupt was lost
            shutdown.delivered = shutdown.presses  # delivered here: not again by the hook
            raise KeyboardInterrupt
        if interrupted is not None and interrupted():
            raise Interrupted
        now = time.monotonic()
        if now >= deadline:
            return None
        if client is not None and now >= next_check:
            if not client.server_is_ready():
                raise ServerLost
            next_check = now + SERVER_CHECK_PERIOD
        spin = min(SPIN_SLICE, period + (now - start) / 10) if slow_down else period
        executor.spin_once(timeout_sec=min(spin, deadline - now))
    return result
