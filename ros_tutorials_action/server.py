"""Action server (book: ros_tutorials_action/action_server).

Serves the Fibonacci action ``ros_tutorial_action``. A goal of order N starts from the seeds
0, 1 and appends one term per step, N steps, publishing the sequence so far as feedback; the
result is the whole sequence. A step takes ``step_period`` seconds (default 1.0: the book's
1 Hz). As with the book's SimpleActionServer, one goal runs at a time: a new goal preempts the
running one, which ends ABORTED (ROS 2 has no PREEMPTED). A cancel ends the goal CANCELED;
Ctrl-C ends it and the server. Orders whose result does not fit in int32 are rejected.

    action_server          (or: python -m ros_tutorials_action.server)
    action_server --ros-args -p step_period:=0.2
"""

import math
import signal
import time

import rclpy
from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.qos import QoSProfile
from rclpy.signals import SignalHandlerOptions
from ros_tutorials_interfaces.action import Fibonacci

from ros_tutorials_common.ros import ros_args

ACTION_NAME = "ros_tutorial_action"
INT32_MAX = 2**31 - 1
MAX_ORDER = 45  # the sequence of order 45 ends at F(46) = 1836311903; F(47) > INT32_MAX
MAX_STEP_PERIOD = 86400.0  # one day
CHECK_PERIOD = 0.05  # how often a step's wait looks for a cancel, a new goal or Ctrl-C
# The action's goal, cancel and result services queue this many requests (rclpy's default: 10).
REQUESTS = QoSProfile(depth=1000)


def step_period_error(value) -> str | None:
    """Why ``value`` is not a usable step period, or None if it is."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return f"step_period must be a number of seconds, not {value!r}"
    if not (math.isfinite(value) and 0 < value <= MAX_STEP_PERIOD):
        limit = f"at most {MAX_STEP_PERIOD:g}"
        return f"step_period must be greater than 0 seconds and {limit}, not {value}"
    return None


class FibonacciActionServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("action_server", enable_logger_service=True, **node_kwargs)
        # dynamic_typing: "-p step_period:=1" (an integer) is as good as 1.0.
        descriptor = ParameterDescriptor(description="seconds per term", dynamic_typing=True)
        self.declare_parameter("step_period", 1.0, descriptor)
        if error := step_period_error(self.get_parameter("step_period").value):
            raise SystemExit(f"error: {error}")
        self.add_on_set_parameters_callback(self.check_step_period)
        self.current_goal = None  # the goal accepted last: any other running goal is preempted
        self.running = []  # the goals whose execute callback runs
        self.stopping = False  # set on Ctrl-C
        # The action server. Reentrant: goal and cancel requests are answered while a goal runs.
        self.action_server = ActionServer(
            self, Fibonacci, ACTION_NAME, self.execute,
            goal_callback=self.on_goal, handle_accepted_callback=self.on_accepted,
            cancel_callback=lambda goal_handle: CancelResponse.ACCEPT,  # rclpy's default: REJECT
            callback_group=ReentrantCallbackGroup(), goal_service_qos_profile=REQUESTS,
            cancel_service_qos_profile=REQUESTS, result_service_qos_profile=REQUESTS,
        )  # fmt: skip

    @property
    def step_period(self) -> float:
        return float(self.get_parameter("step_period").value)

    def check_step_period(self, parameters) -> SetParametersResult:
        for parameter in parameters:
            error = parameter.name == "step_period" and step_period_error(parameter.value)
            if error:
                return SetParametersResult(successful=False, reason=error)
        return SetParametersResult(successful=True)

    def on_goal(self, goal: Fibonacci.Goal) -> GoalResponse:
        if 0 <= goal.order <= MAX_ORDER:
            return GoalResponse.ACCEPT
        self.get_logger().warning(
            f"{ACTION_NAME}: Rejected goal of order {goal.order}: the order must be 0 to "
            f"{MAX_ORDER}, so that the sequence fits in int32"
        )
        return GoalResponse.REJECT

    def on_accepted(self, goal_handle) -> None:
        self.current_goal = goal_handle  # preempts the goal that runs, if one does
        goal_handle.execute()

    def should_stop(self, goal_handle) -> bool:
        # The book: as_.isPreemptRequested() || !ros::ok()
        preempted = goal_handle is not self.current_goal
        return goal_handle.is_cancel_requested or preempted or self.stopping

    def execute(self, goal_handle) -> Fibonacci.Result:
        """The execute callback: compute the sequence, one term and one feedback per step."""
        self.running.append(goal_handle)
        order = goal_handle.request.order
        sequence = [0, 1]  # the seeds
        self.get_logger().info(
            f"{ACTION_NAME}: Executing, creating fibonacci sequence of order {order} "
            f"with seeds {sequence[0]}, {sequence[1]}"
        )
        for _ in range(order):
            if self.should_stop(goal_handle):
                break
            sequence.append(sequence[-1] + sequence[-2])
            goal_handle.publish_feedback(Fibonacci.Feedback(sequence=sequence))
            # Sleep one step, but look every CHECK_PERIOD whether the goal should stop.
            end = time.monotonic() + self.step_period
            while not self.should_stop(goal_handle) and time.monotonic() < end:
                time.sleep(min(CHECK_PERIOD, max(0.0, end - time.monotonic())))
        # The goal's final state; the partial sequence is the result of a stopped goal.
        if goal_handle.is_cancel_requested:
            goal_handle.canceled()
            self.get_logger().info(f"{ACTION_NAME}: Canceled")
        elif goal_handle is not self.current_goal or self.stopping:
            goal_handle.abort()
            self.get_logger().info(f"{ACTION_NAME}: Preempted")
        else:
            goal_handle.succeed()
            self.get_logger().info(f"{ACTION_NAME}: Succeeded")
        self.running.remove(goal_handle)
        return Fibonacci.Result(sequence=sequence)

    def destroy_node(self) -> None:
        # A running goal uses this node: stop it first, and wait (at most 5 s) until it has.
        self.stopping = True
        end = time.monotonic() + 5.0
        while self.running and time.monotonic() < end:
            time.sleep(CHECK_PERIOD)
        self.action_server.destroy()
        super().destroy_node()


def main(args=None) -> None:
    # Ctrl-C and SIGTERM raise KeyboardInterrupt, and ROS stays up until the running goal has
    # stopped: with rclpy's own handler, ROS would shut down under the goal's feet.
    rclpy.init(args=ros_args(args), signal_handler_options=SignalHandlerOptions.NO)
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    executor = MultiThreadedExecutor(num_threads=4)  # a goal runs in one thread, requests in others
    node = None
    try:
        node = FibonacciActionServer()  # create the node and its action server
        executor.add_node(node)
        while True:  # spin: wait for goals and execute them, until Ctrl-C ...
            executor.spin_once(timeout_sec=0.1)  # ... which Python sees between two waits
    except KeyboardInterrupt:  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
        signal.signal(signal.SIGINT, signal.SIG_IGN)  # a second one must not cut the stop short
    finally:
        if node is not None:
            node.destroy_node()  # stops the running goal first
        executor.shutdown()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
