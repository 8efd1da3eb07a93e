"""Action client (book: ros_tutorials_action/action_client): sends one Fibonacci goal to
``ros_tutorial_action``, logs each feedback, the result and the final state, and exits.

    action_client [ORDER]   (or: python -m ros_tutorials_action.client [ORDER]; --help)
"""

import sys

import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from ros_tutorials_interfaces.action import Fibonacci

from ros_tutorials_common.ros import action_client_steps as steps

ACTION_NAME = "ros_tutorial_action"


def main(args=None) -> int:
    options = steps.parse_args(args)  # ORDER (default 20), --timeout, --result-timeout
    # Ctrl-C raises KeyboardInterrupt, and ROS stays up, so that the goal can still be canceled.
    rclpy.init(args=steps.ros_args(args), signal_handler_options=SignalHandlerOptions.NO)
    node = Node("action_client", enable_logger_service=True)  # create the node
    client = ActionClient(node, Fibonacci, ACTION_NAME)  # and the action client
    waits = steps.GoalWaits(node, client, ACTION_NAME)  # waits with a time limit; cancel
    log = node.get_logger()

    def on_feedback(msg: Fibonacci.Impl.FeedbackMessage) -> None:  # the feedback callback
        log.info(f"Received feedback: {list(msg.feedback.sequence)}")

    def on_result(response: Fibonacci.Impl.GetResultService.Response) -> int:  # result, state
        log.info(f"Result: {list(response.result.sequence)}")
        log.info(f"Action finished: {steps.state_name(response.status)}")
        return 0 if response.status == GoalStatus.STATUS_SUCCEEDED else 1

    try:
        log.info("Waiting for action server to start.")
        if not client.wait_for_server(timeout_sec=options.timeout):  # wait for the server
            log.error(f"Action server {ACTION_NAME} not available after {options.timeout:g} s")
            return 1
        log.info("Action server started, sending goal.")
        goal = Fibonacci.Goal(order=options.order)  # send the goal, with the feedback callback
        goal_future = client.send_goal_async(goal, feedback_callback=on_feedback)
        goal_handle = waits.accepted(goal_future, goal, options.timeout)  # None: said why not
        if goal_handle is None:
            return 1
        result_future = goal_handle.get_result_async()  # ask for the result, and wait for it
        if waits.done(result_future, options.result_timeout):
            return on_result(result_future.result())
        if not waits.server_gone():  # no result in time: the book's line; cancel the goal
            log.warning("Action did not finish before the time out.")
            waits.cancel(on_result)
        return 1
    except KeyboardInterrupt:  # Ctrl-C: cancel the goal, then exit status 130
        waits.cancel(on_result)
        return steps.EXIT_INTERRUPTED
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down


if __name__ == "__main__":
    sys.exit(main())
