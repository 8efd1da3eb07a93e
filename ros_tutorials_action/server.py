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

import rclpy
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from ros_tutorials_interfaces.action import Fibonacci

from ros_tutorials_common.ros import action_server_steps as steps
from ros_tutorials_common.ros.action_server_steps import REQUESTS

ACTION_NAME = "ros_tutorial_action"
INT32_MAX = 2**31 - 1
MAX_ORDER = 45  # the sequence of order 45 ends at F(46) = 1836311903; F(47) > INT32_MAX


class FibonacciActionServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("action_server", enable_logger_service=True, **node_kwargs)
        steps.declare_step_period(self)  # seconds per step (default 1.0), checked
        self.current_goal = None  # the goal accepted last: any other running goal is preempted
        self.goals = steps.RunningGoals()  # so that Ctrl-C can stop the running goal first
        # The action server. Reentrant: goal and cancel requests are answered while a goal runs.
        self.action_server = ActionServer(
            self, Fibonacci, ACTION_NAME, self.goals.track(self.execute),
            goal_callback=self.on_goal, handle_accepted_callback=self.on_accepted,
            cancel_callback=lambda goal_handle: CancelResponse.ACCEPT,  # rclpy's default: REJECT
            callback_group=ReentrantCallbackGroup(), goal_service_qos_profile=REQUESTS,
            cancel_service_qos_profile=REQUESTS, result_service_qos_profile=REQUESTS,
        )  # fmt: skip

    @property
    def step_period(self) -> float:
        return float(self.get_parameter("step_period").value)

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
        return goal_handle.is_cancel_requested or preempted or self.goals.stopping

    def execute(self, goal_handle) -> Fibonacci.Result:
        """The execute callback: compute the sequence, one term and one feedback per step."""
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
            steps.sleep_unless(lambda: self.should_stop(goal_handle), self.step_period)
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
        return Fibonacci.Result(sequence=sequence)

    def destroy_node(self) -> None:
        self.goals.stop()  # a running goal uses this node: stop it first (waits at most 5 s)
        self.action_server.destroy()
        super().destroy_node()


def main(args=None) -> None:
    # Ctrl-C and SIGTERM raise KeyboardInterrupt, and ROS stays up until the running goal has
    # stopped: with rclpy's own handler, ROS would shut down under the goal's feet.
    rclpy.init(args=steps.ros_args(args), signal_handler_options=SignalHandlerOptions.NO)
    steps.ctrl_c_raises()
    executor = MultiThreadedExecutor(num_threads=4)  # a goal runs in one thread, requests in others
    node = None
    try:
        node = FibonacciActionServer()  # create the node and its action server
        executor.add_node(node)
        while True:  # spin: wait for goals and execute them, until Ctrl-C ...
            executor.spin_once(timeout_sec=0.1)  # ... which Python sees between two waits
    except KeyboardInterrupt:  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
        steps.ignore_ctrl_c()  # a second one must not cut the stop short
    finally:
        if node is not None:
            node.destroy_node()  # stops the running goal first
        executor.shutdown()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
