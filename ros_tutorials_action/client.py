"""Action client (book: ros_tutorials_action/action_client): sends one Fibonacci goal to
``ros_tutorial_action``, logs each feedback, the result and the final state, and exits."""

import argparse
import sys
import time

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from rclpy.utilities import remove_ros_args
from ros_tutorials_interfaces.action import Fibonacci

ACTION_NAME = "ros_tutorial_action"


def main(args: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="action_client")  # else usage, exit status 2
    parser.add_argument("order", metavar="ORDER", type=int, nargs="?", default=20)
    parser.add_argument("--timeout", metavar="SECONDS", type=float, default=10.0)
    parser.add_argument("--result-timeout", metavar="SECONDS", type=float, default=30.0)
    options = parser.parse_args(remove_ros_args(args or sys.argv)[1:])
    if not -(2**31) <= options.order < 2**31:
        parser.error(f"ORDER: {options.order} does not fit in a 32-bit integer")
    if not (0 < options.timeout <= 1e6 and 0 < options.result_timeout <= 1e6):  # nan, inf too
        parser.error("--timeout, --result-timeout: a positive number of seconds up to 1e6")

    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)  # Ctrl-C: see below
    node = Node("action_client", enable_logger_service=True)  # create the node
    client = ActionClient(node, Fibonacci, ACTION_NAME)  # and the action client
    log = node.get_logger()

    def wait(future, timeout: float) -> bool:  # while the server is there; short spins: Ctrl-C
        end = time.monotonic() + timeout
        while not future.done() and time.monotonic() < end and client.server_is_ready():
            rclpy.spin_once(node, timeout_sec=0.1)
        return future.done()

    def on_feedback(msg: Fibonacci.Impl.FeedbackMessage) -> None:  # the feedback callback
        log.info(f"Received feedback: {list(msg.feedback.sequence)}")

    def finished(response: Fibonacci.Impl.GetResultService.Response) -> int:  # result, state
        state = {4: "SUCCEEDED", 5: "CANCELED", 6: "ABORTED"}.get(response.status, response.status)
        log.info(f"Result: {list(response.result.sequence)}")
        log.info(f"Action finished: {state}")
        return 0 if state == "SUCCEEDED" else 1

    sent = status = None  # status: set on a time out (1) or Ctrl-C (130), to cancel the goal
    try:
        log.info("Waiting for action server to start.")
        if not client.wait_for_server(timeout_sec=options.timeout):  # wait for the server
            log.error(f"Action server {ACTION_NAME} not available after {options.timeout:g} s")
            return 1
        log.info("Action server started, sending goal.")  # with the feedback callback
        sent = client.send_goal_async(Fibonacci.Goal(order=options.order), on_feedback)
        if not wait(sent, options.timeout):
            log.error(f"No answer from action server {ACTION_NAME} to the goal")
            return 1
        if not sent.result().accepted:
            log.error(f"Goal of order {options.order} rejected (the server's log says why)")
            return 1
        result = sent.result().get_result_async()  # ask for the result, wait for it
        if wait(result, options.result_timeout):
            return finished(result.result())
        if not client.server_is_ready():
            log.error(f"Action server {ACTION_NAME} went away before the goal finished")
            return 1
        log.warning("Action did not finish before the time out.")  # the book's line
        status = 1
    except KeyboardInterrupt:  # without rclpy's handler, ROS stays up to cancel the goal
        status = 130  # Ctrl-C: the exit status a shell gives a command it interrupted
    finally:  # on a time out or Ctrl-C, cancel the goal if the server took it (5 s per wait)
        if status and sent and wait(sent, 5.0) and sent.result().accepted:
            log.info("Canceling goal")
            sent.result().cancel_goal_async()
            if wait(result := sent.result().get_result_async(), 5.0):
                finished(result.result())
        node.destroy_node()
        rclpy.try_shutdown()  # shut ROS 2 down
    return status


if __name__ == "__main__":
    sys.exit(main())
