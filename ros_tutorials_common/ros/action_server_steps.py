"""What the action lesson's server does besides the book's steps; a learner can skip this.

The book's server runs the execute callback at 1 Hz until the goal is done or preempted. A
server that many clients use, and that a user stops with Ctrl-C, has to do more: check its
``step_period`` parameter, queue more requests than rclpy's default (10), notice a cancel or a
new goal within a step instead of at its end, and stop the running goal before ROS shuts down
(or the goal's thread runs into a destroyed node). Those parts live here:

- ``declare_step_period(node)``: the parameter, checked at start and at every change;
- ``REQUESTS``: the queue depth of the action's goal, cancel and result services;
- ``sleep_unless(stop, seconds)``: one step's sleep, cut short when ``stop()`` becomes true;
- ``RunningGoals``: which goals execute, so that shutdown stops them first;
- ``ctrl_c_raises()`` / ``ignore_ctrl_c()``: Ctrl-C and SIGTERM raise KeyboardInterrupt (ROS
  stays up until the lesson shuts it down), and a second one cannot cut the shutdown short.
"""

from __future__ import annotations

import math
import signal
import threading
import time
from collections.abc import Callable
from typing import Any

from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import QoSProfile

from ros_tutorials_common.ros.node_main import ros_args

__all__ = [
    "REQUESTS",
    "RunningGoals",
    "ctrl_c_raises",
    "declare_step_period",
    "ignore_ctrl_c",
    "ros_args",
    "sleep_unless",
]
MAX_STEP_PERIOD = 86400.0  # one day: far below what a thread can wait for
CHECK_PERIOD = 0.05  # how often a step's sleep looks whether the goal should stop
STOP_TIMEOUT = 5.0  # how long shutdown waits for the running goals to stop
# The action's goal, cancel and result services queue this many requests (rclpy's default: 10,
# and a storm of requests beyond that was lost).
REQUESTS = QoSProfile(depth=1000)


def step_period_error(value: Any) -> str | None:
    """Why ``value`` is not a usable step period, or None if it is."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return f"step_period must be a number of seconds, not {value!r}"
    if not (math.isfinite(value) and 0 < value <= MAX_STEP_PERIOD):
        limit = f"at most {MAX_STEP_PERIOD:g}"
        return f"step_period must be greater than 0 seconds and {limit}, not {value}"
    return None


def declare_step_period(node: Node, default: float = 1.0) -> None:
    """Declare the parameter ``step_period`` (seconds per step; an integer will do), end the
    program with one line if its value at start is unusable, and refuse unusable changes."""
    descriptor = ParameterDescriptor(description="seconds per term", dynamic_typing=True)
    node.declare_parameter("step_period", default, descriptor)
    if error := step_period_error(node.get_parameter("step_period").value):
        raise SystemExit(f"error: {error}")

    def check(parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            error = parameter.name == "step_period" and step_period_error(parameter.value)
            if error:
                return SetParametersResult(successful=False, reason=error)
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(check)


def sleep_unless(stop: Callable[[], bool], seconds: float) -> None:
    """Sleep ``seconds`` (the book's ``r.sleep()``), looking every CHECK_PERIOD whether
    ``stop()`` has become true, and returning at once if it has."""
    end = time.monotonic() + seconds
    while not stop() and time.monotonic() < end:
        time.sleep(min(CHECK_PERIOD, max(0.0, end - time.monotonic())))


class RunningGoals:
    """The goals whose execute callback runs. ``stop()`` asks them to stop (``stopping``) and
    waits, at most STOP_TIMEOUT seconds, until they have: a running goal uses the node, so
    shutdown calls it before destroying the action server and the node."""

    def __init__(self) -> None:
        self.stopping = False
        self._running: set[int] = set()
        self._lock = threading.Lock()

    def track(self, execute: Callable[[Any], Any]) -> Callable[[Any], Any]:
        """The execute callback, counted as running while it runs."""

        def tracked(goal_handle: Any) -> Any:
            with self._lock:
                self._running.add(id(goal_handle))
            try:
                return execute(goal_handle)
            finally:
                with self._lock:
                    self._running.discard(id(goal_handle))

        return tracked

    def stop(self) -> None:
        self.stopping = True
        end = time.monotonic() + STOP_TIMEOUT
        while self._running and time.monotonic() < end:
            time.sleep(CHECK_PERIOD)


def ctrl_c_raises() -> None:
    """SIGTERM, like Ctrl-C (SIGINT), raises KeyboardInterrupt in the main thread. Give rclpy.init
    ``signal_handler_options=SignalHandlerOptions.NO`` as well, so that rclpy's own handler
    does not shut ROS down under a running goal's feet."""
    signal.signal(signal.SIGTERM, signal.default_int_handler)


def ignore_ctrl_c() -> None:
    """Once stopping: a second Ctrl-C or SIGTERM must not cut the shutdown short."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
