"""Action server (book: ros_tutorials_action/action_server): the Fibonacci action
``ros_tutorial_action``, one term and one feedback per ``step_period`` seconds (default 1.0: the
book's 1 Hz) from the seeds 0, 1. One goal runs at a time, as with the book's SimpleActionServer:
a new goal preempts it (ABORTED), a cancel ends it CANCELED. Orders whose result does not fit in
int32 are rejected.    action_server --ros-args -p step_period:=0.2"""

import time

import rclpy
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.node import Node
from rclpy.qos import QoSProfile
from ros_tutorials_interfaces.action import Fibonacci

ACTION_NAME = "ros_tutorial_action"
MAX_ORDER = 45  # the sequence of order 45 ends at F(46) = 1836311903; F(47) > int32's maximum
REQUESTS = QoSProfile(depth=1000)  # the goal, cancel, result services' queues (10 lost some)


class FibonacciActionServer(Node):
    def __init__(self, **node_kwargs) -> None:
        super().__init__("action_server", **node_kwargs)
        self.declare_parameter("step_period", 1.0)  # seconds per term
        self.current_goal = None  # the goal accepted last: any other running goal stops
        self.action_server = ActionServer(  # reentrant: requests are answered while a goal runs
            self, Fibonacci, ACTION_NAME, self.execute,
            goal_callback=self.on_goal, handle_accepted_callback=self.on_accepted,
            cancel_callback=lambda goal_handle: CancelResponse.ACCEPT,  # rclpy's default: REJECT
            callback_group=ReentrantCallbackGroup(), goal_service_qos_profile=REQUESTS,
            cancel_service_qos_profile=REQUESTS, result_service_qos_profile=REQUESTS,
        )  # fmt: skip

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

    def should_stop(self, goal_handle) -> bool:  # the book: isPreemptRequested() || !ros::ok()
        preempted = goal_handle.is_cancel_requested or goal_handle is not self.current_goal
        return preempted or not self.context.ok()

    def execute(self, goal_handle) -> Fibonacci.Result:
        """The execute callback: compute the sequence, one term and one feedback per step."""
        order, sequence = goal_handle.request.order, [0, 1]  # the seeds
        self.get_logger().info(
            f"{ACTION_NAME}: Executing, creating fibonacci sequence of order {order} "
            f"with seeds {sequence[0]}, {sequence[1]}"
        )
        for _ in range(order):
            if self.should_stop(goal_handle):
                break
            sequence.append(sequence[-1] + sequence[-2])
            goal_handle.publish_feedback(Fibonacci.Feedback(sequence=sequence))
            # The book's r.sleep(), looking every 0.1 s: a cancel, a new goal or Ctrl-C ends it.
            step_period = self.get_parameter("step_period").value
            end = time.monotonic() + step_period
            while time.monotonic() < end and not self.should_stop(goal_handle):
                time.sleep(min(step_period, 0.1))
        if goal_handle.is_cancel_requested:  # the final state (a stopped goal: partial result)
            goal_handle.canceled()
            self.get_logger().info(f"{ACTION_NAME}: Canceled")
        elif self.should_stop(goal_handle):  # a newer goal came, or Ctrl-C
            goal_handle.abort()
            self.get_logger().info(f"{ACTION_NAME}: Preempted")
        else:
            goal_handle.succeed()
            self.get_logger().info(f"{ACTION_NAME}: Succeeded")
        return Fibonacci.Result(sequence=sequence)


def main(args: list[str] | None = None) -> None:
    rclpy.init(args=args)  # initialise ROS 2 (reads --ros-args)
    node = FibonacciActionServer()  # create the node and its action server
    try:
        # spin: wait for goals and execute them, a goal in one thread, requests in the others
        rclpy.spin(node, executor=MultiThreadedExecutor(num_threads=4))
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl-C or SIGTERM: the normal way to stop (exit status 0)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    main()
