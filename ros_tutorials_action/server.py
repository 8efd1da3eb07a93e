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

import time

import rclpy
from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import QoSProfile
from rclpy.signals import SignalHandlerOptions
from ros_tutorials_interfaces.action import Fibonacci

ACTION_NAME = "ros_tutorial_action"
INT32_MAX = 2**31 - 1
MAX_ORDER = 45  # the sequence of order 45 ends at F(46) = 1836311903; F(47) > INT32_MAX
MAX_STEP_PERIOD = 86400.0  # one day: far below what a thread can wait for
# The goal, cancel and result services queue this many requests (rclpy's default, 10, lost some).
REQUESTS = QoSProfile(depth=1000)


def step_period_error(value: object) -> str | None:
    """Why value is not a usable step_period, or None if it is."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return f"step_period must be a number of seconds, not {value!r}"
    if not 0 < value <= MAX_STEP_PERIOD:  # nan too
        return f"step_period must be greater than 0 seconds and at most 86400, not {value}"
    return None


class FibonacciActionServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("action_server", enable_logger_service=True, **node_kwargs)
        # Seconds per step (an integer will do), checked at start and at every change.
        descriptor = ParameterDescriptor(description="seconds per term", dynamic_typing=True)
        self.declare_parameter("step_period", 1.0, descriptor)
        if error := step_period_error(self.step_period):
            raise SystemExit(f"error: {error}")
        self.add_on_set_parameters_callback(self.check_step_period)
        self.current_goal = None  # the goal accepted last: any other running goal is preempted
        self.running = []  # the goals whose execute callback runs
        self.stopping = False  # set on Ctrl-C: every running goal stops
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
        return self.get_parameter("step_period").value

    def check_step_period(self, parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            if parameter.name == "step_period" and (error := step_period_error(parameter.value)):
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
            # Sleep one step (the book: r.sleep()), but stop at once if the goal should stop.
            end = time.monotonic() + self.step_period
            while time.monotonic() < end and not self.should_stop(goal_handle):
                time.sleep(0.05)
        # The goal's final state; the partial sequence is the result of a stopped goal.
        if goal_handle.is_cancel_requested:
            goal_handle.canceled()
            self.get_logger().info(f"{ACTION_NAME}: Canceled")
        elif self.should_stop(goal_handle):  # a newer goal came, or Ctrl-C
            goal_handle.abort()
            self.get_logger().info(f"{ACTION_NAME}: Preempted")
        else:
            goal_handle.succeed()
            self.get_logger().info(f"{ACTION_NAME}: Succeeded")
        self.running.remove(goal_handle)
        return Fibonacci.Result(sequence=sequence)

    def destroy_node(self) -> None:
        # A running goal uses this node: stop it first (waiting 5 s at most).
        self.stopping = True
        end = time.monotonic() + 5.0
        while self.running and time.monotonic() < end:
            time.sleep(0.05)
        self.action_server.destroy()
        super().destroy_node()


def main(args: list[str] | None = None) -> None:
    # Without rclpy's signal handler, Ctrl-C raises KeyboardInterrupt and ROS stays up until
    # the running goal has stopped: with it, ROS would shut down under the goal's feet.
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = FibonacciActionServer()  # create the node and its action server
    executor = MultiThreadedExecutor(num_threads=4)  # a goal runs in one thread, requests in others
    executor.add_node(node)
    try:
        while True:  # spin: wait for goals and execute them, in short spins ...
            executor.spin_once(timeout_sec=0.1)  # ... so that Python sees Ctrl-C between two
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()  # stops the running goal first
        executor.shutdown()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
