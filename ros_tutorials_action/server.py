"""Action server (book: ros_tutorials_action/action_server).

Serves the action ``ros_tutorial_action`` (ros_tutorials_interfaces/action/Fibonacci). A goal
of order N starts from the seeds [0, 1] and appends one term per step, N steps, publishing
the partial sequence as feedback after each term; the result is the whole sequence (N + 2
terms, as in the book). One step takes ``step_period`` seconds (parameter, default 1.0: the
book's 1 Hz).

- Goals the int32 result cannot hold (a negative order, or an order above MAX_ORDER) are
  rejected with a log line; the server keeps running.
- Cancel requests are accepted: the goal stops within one step and ends CANCELED with the
  partial sequence as its result.
- A new goal preempts the running one, as the book's SimpleActionServer does: the running
  goal stops, logs "Preempted" and ends ABORTED (ROS 2 has no PREEMPTED state) with its
  partial sequence; the new goal then runs.

    python -m ros_tutorials_action.server        (or: action_server)
    action_server --ros-args -p step_period:=0.2
"""

from __future__ import annotations

import math
import threading
import time

from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.action.server import ServerGoalHandle
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.context import Context
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from ros_tutorials_interfaces.action import Fibonacci

from ros_tutorials_common.node_main import run_node

ACTION_NAME = "ros_tutorial_action"
INT32_MAX = 2**31 - 1


def largest_order() -> int:
    """The largest order whose sequence fits in int32 (the sequence of order N ends at F(N+1))."""
    previous, last, order = 0, 1, 0
    while previous + last <= INT32_MAX:
        previous, last, order = last, previous + last, order + 1
    return order


MAX_ORDER = largest_order()  # 45: F(46) = 1836311903 fits, F(47) = 2971215073 does not


def step_period_error(value: object) -> str | None:
    """Why ``value`` is not a usable step period, or None if it is."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return f"step_period must be a number of seconds, not {value!r}"
    if not (math.isfinite(value) and value > 0):
        return f"step_period must be greater than 0 seconds, not {value}"
    return None


class _Run:
    """A goal being executed, and why it should stop early (if it should)."""

    def __init__(self, goal_handle: ServerGoalHandle) -> None:
        self.goal_handle = goal_handle
        self.wake = threading.Event()  # set to end the current step's wait at once
        self.cancel_requested = False
        self.preempted = False


class FibonacciActionServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("action_server", enable_logger_service=True, **node_kwargs)
        # dynamic_typing: "-p step_period:=1" (an integer) is as good as 1.0.
        self.declare_parameter(
            "step_period",
            1.0,
            ParameterDescriptor(description="seconds per Fibonacci term", dynamic_typing=True),
        )
        error = step_period_error(self.get_parameter("step_period").value)
        if error:
            raise SystemExit(f"error: {error}")
        self.add_on_set_parameters_callback(self.on_set_parameters)

        self._runs: dict[bytes, _Run] = {}
        self._runs_changed = threading.Condition()
        self._stopping = False
        # Reentrant: the goal, cancel and result callbacks of this action server may run
        # while a goal executes (in another thread of a MultiThreadedExecutor).
        self.action_server = ActionServer(
            self,
            Fibonacci,
            ACTION_NAME,
            execute_callback=self.execute,
            goal_callback=self.on_goal,
            handle_accepted_callback=self.on_accepted,
            cancel_callback=self.on_cancel,
            callback_group=ReentrantCallbackGroup(),
        )

    @property
    def step_period(self) -> float:
        return float(self.get_parameter("step_period").value)

    def on_set_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            error = parameter.name == "step_period" and step_period_error(parameter.value)
            if error:
                return SetParametersResult(successful=False, reason=error)
        return SetParametersResult(successful=True)

    def on_goal(self, goal: Fibonacci.Goal) -> GoalResponse:
        if not 0 <= goal.order <= MAX_ORDER:
            self.get_logger().warning(
                f"{ACTION_NAME}: Rejected goal of order {goal.order}: the order must be 0 to "
                f"{MAX_ORDER}, so that the sequence fits in int32"
            )
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def on_accepted(self, goal_handle: ServerGoalHandle) -> None:
        with self._runs_changed:
            for run in self._runs.values():  # at most one: the goal this one preempts
                run.preempted = True
                run.wake.set()
            self._runs[_key(goal_handle)] = _Run(goal_handle)
        goal_handle.execute()

    def on_cancel(self, goal_handle: ServerGoalHandle) -> CancelResponse:
        with self._runs_changed:
            run = self._runs.get(_key(goal_handle))
            # No run yet: the goal was accepted but on_accepted has not run; execute() will see
            # goal_handle.is_cancel_requested. (rclpy does not ask about finished goals.)
            if run is not None:
                run.cancel_requested = True
                run.wake.set()
        return CancelResponse.ACCEPT

    def execute(self, goal_handle: ServerGoalHandle) -> Fibonacci.Result:
        with self._runs_changed:
            run = self._runs[_key(goal_handle)]
        order = goal_handle.request.order
        sequence = [0, 1]
        self.get_logger().info(
            f"{ACTION_NAME}: Executing, creating fibonacci sequence of order {order} "
            f"with seeds {sequence[0]}, {sequence[1]}"
        )
        for _ in range(order):
            if run.wake.is_set() or self._stopping or goal_handle.is_cancel_requested:
                break
            sequence.append(sequence[-1] + sequence[-2])
            goal_handle.publish_feedback(Fibonacci.Feedback(sequence=sequence))
            # Not time.sleep: a cancel, a new goal or shutdown sets `wake` and ends the step now.
            run.wake.wait(self.step_period)
        self._finish(run)
        return Fibonacci.Result(sequence=sequence)

    def _finish(self, run: _Run) -> None:
        """Put the goal in its final state and forget it, holding the lock all along so that
        a cancel or a new goal cannot change its fate half way."""
        goal_handle, log = run.goal_handle, self.get_logger()
        if run.cancel_requested:
            _wait_until_canceling(goal_handle)  # not holding the lock: other goals go on
        with self._runs_changed:
            if run.cancel_requested or goal_handle.is_cancel_requested:
                _wait_until_canceling(goal_handle)  # at once, unless a cancel just came in
                goal_handle.canceled()
                log.info(f"{ACTION_NAME}: Canceled")
            elif run.preempted:
                goal_handle.abort()
                log.info(f"{ACTION_NAME}: Preempted")
            elif self._stopping:
                goal_handle.abort()
                if self.context.ok():  # after Ctrl-C, logging would only complain about rosout
                    log.info(f"{ACTION_NAME}: Aborted, the server is shutting down")
            else:
                goal_handle.succeed()
                log.info(f"{ACTION_NAME}: Succeeded")
            del self._runs[_key(goal_handle)]
            self._runs_changed.notify_all()

    def destroy_node(self) -> None:
        # A running goal holds an executor thread, and Python waits for those threads at exit:
        # stop the goals first. While ROS is up they end ABORTED, and their clients hear it.
        # After Ctrl-C rclpy has already shut ROS down and nobody can be told: destroying the
        # action server first turns the goals' state changes into no-ops instead of errors.
        ros_up = self.context.ok()
        if not ros_up:
            self.action_server.destroy()
        with self._runs_changed:
            self._stopping = True
            for run in self._runs.values():
                run.wake.set()
            self._runs_changed.wait_for(lambda: not self._runs, timeout=5.0)
        if ros_up:
            self.action_server.destroy()
        super().destroy_node()


def _key(goal_handle: ServerGoalHandle) -> bytes:
    return bytes(goal_handle.goal_id.uuid)


def _wait_until_canceling(goal_handle: ServerGoalHandle, timeout: float = 5.0) -> None:
    # rclpy moves the goal to CANCELING just after on_cancel returns ACCEPT, in the thread that
    # called it; this thread may get here first, and CANCELED is only valid from CANCELING.
    deadline = time.monotonic() + timeout
    while not goal_handle.is_cancel_requested and time.monotonic() < deadline:
        time.sleep(0.001)


def make_executor(context: Context | None = None) -> MultiThreadedExecutor:
    """One thread executes the goal while others answer goal, cancel and result requests."""
    return MultiThreadedExecutor(num_threads=4, context=context)


def main() -> int:
    return run_node(FibonacciActionServer, make_executor=make_executor)


if __name__ == "__main__":
    raise SystemExit(main())
