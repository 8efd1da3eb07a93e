"""The action lesson: the Fibonacci server in-process, and the client CLI as a real process.

Goals that must not finish on their own run with a step period of an hour: if the server only
noticed a cancel, a new goal or a shutdown at the end of a step, these tests would time out.
"""

from __future__ import annotations

import ast
import os
import re
import signal
import threading
from collections.abc import Callable, Iterator

import pytest
from action_msgs.msg import GoalStatus, GoalStatusArray
from cpu_load import CpuLoad
from helpers import BIN, TIMEOUT, spin_until
from rclpy.action import ActionClient
from rclpy.action.client import ClientGoalHandle
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import qos_profile_action_status_default
from ros_tutorials_interfaces.action import Fibonacci

from ros_tutorials_action.server import ACTION_NAME, MAX_ORDER, FibonacciActionServer

INT32_MAX = 2**31 - 1

FAST = 0.01  # seconds per step, for goals that should finish
FOREVER = 3600.0  # seconds per step, for goals that must be stopped
CLIENT = ("-m", "ros_tutorials_action.client")


def fibonacci(order: int) -> list[int]:
    """The book's sequence of an order: the seeds 0, 1 and `order` more terms."""
    sequence = [0, 1]
    for _ in range(order):
        sequence.append(sequence[-1] + sequence[-2])
    return sequence


@pytest.fixture
def start_server(context) -> Iterator[Callable[[float], FibonacciActionServer]]:
    """Start the action server in this process, spun by its own multi-threaded executor."""
    started = []

    def start(step_period: float) -> FibonacciActionServer:
        server = FibonacciActionServer(
            context=context, parameter_overrides=[Parameter("step_period", value=step_period)]
        )
        executor = MultiThreadedExecutor(num_threads=4, context=context)  # as the server's main
        executor.add_node(server)
        stop = threading.Event()

        def spin() -> None:
            while not stop.is_set():
                executor.spin_once(timeout_sec=0.1)

        thread = threading.Thread(target=spin, daemon=True)
        thread.start()
        started.append((server, executor, stop, thread))
        return server

    yield start
    for server, executor, stop, thread in started:
        stop_server(server, executor, stop, thread)


def stop_server(server: FibonacciActionServer, executor, stop, thread) -> None:
    """Stop a running goal (as a newer goal would), the spin, the executor (which waits for
    the goal's thread), then the action server (rclpy's destroy_node leaves it) and the node."""
    server.current_goal = None
    stop.set()
    thread.join()
    executor.shutdown()
    server.action_server.destroy()
    server.destroy_node()


class Probe:
    """A test's own action client, plus what the action's status topic says about each goal."""

    def __init__(self, context, executor) -> None:
        self.executor = executor
        self.node = Node("probe", context=context)
        self.client = ActionClient(self.node, Fibonacci, ACTION_NAME)
        self.statuses: dict[bytes, int] = {}
        self.node.create_subscription(
            GoalStatusArray,
            f"{ACTION_NAME}/_action/status",
            self.on_status,
            qos_profile_action_status_default,
        )
        # Every feedback message, straight from the topic: rclpy's client drops feedback that
        # arrives before it has handled the goal's acceptance (likely at 0.01 s per step on a
        # loaded machine), so its feedback callback may miss the first steps.
        self.feedback: dict[bytes, list[list[int]]] = {}
        self.node.create_subscription(
            Fibonacci.Impl.FeedbackMessage,
            f"{ACTION_NAME}/_action/feedback",
            self.on_feedback,
            10,
        )
        executor.add_node(self.node)

    def on_feedback(self, msg) -> None:
        goal = bytes(msg.goal_id.uuid)
        self.feedback.setdefault(goal, []).append(list(msg.feedback.sequence))

    def feedback_of(self, goal_handle: ClientGoalHandle) -> list[list[int]]:
        return self.feedback.get(bytes(goal_handle.goal_id.uuid), [])

    def on_status(self, msg: GoalStatusArray) -> None:
        for status in msg.status_list:
            self.statuses[bytes(status.goal_info.goal_id.uuid)] = status.status

    def send(self, order: int) -> tuple[ClientGoalHandle, list[list[int]]]:
        """Send a goal; its handle once the server answered, and the feedback list it fills."""
        spin_until(self.executor, self.client.server_is_ready, what="the action server")
        feedback: list[list[int]] = []
        future = self.client.send_goal_async(
            Fibonacci.Goal(order=order),
            feedback_callback=lambda msg: feedback.append(list(msg.feedback.sequence)),
        )
        spin_until(self.executor, future.done, what=f"the answer to a goal of order {order}")
        return future.result(), feedback

    def result(self, goal_handle: ClientGoalHandle) -> tuple[int, list[int]]:
        future = goal_handle.get_result_async()
        spin_until(self.executor, future.done, what="the result of a goal")
        return future.result().status, list(future.result().result.sequence)

    def wait_for_status(self, status: int) -> None:
        spin_until(
            self.executor,
            lambda: status in self.statuses.values(),
            what=f"a goal with status {status} on the status topic",
        )


@pytest.fixture
def probe(context, executor) -> Probe:
    return Probe(context, executor)


def test_max_order_is_the_largest_that_fits_in_int32():
    assert fibonacci(MAX_ORDER)[-1] <= INT32_MAX < fibonacci(MAX_ORDER + 1)[-1]
    assert MAX_ORDER == 45  # the book's note: F(47) does not fit


def test_goal_succeeds_with_one_feedback_per_step(start_server, probe):
    server = start_server(FAST)
    # Feedback is a topic: make sure the probe's subscription is known before the goal starts.
    spin_until(
        probe.executor,
        lambda: server.count_subscribers(f"/{ACTION_NAME}/_action/feedback") >= 2,
        what="the probe's feedback subscriptions",
    )
    goal_handle, _ = probe.send(8)
    assert goal_handle.accepted

    assert probe.result(goal_handle) == (GoalStatus.STATUS_SUCCEEDED, fibonacci(8))
    # The result may be handled before the last feedback messages, which travel apart.
    spin_until(
        probe.executor,
        lambda: len(probe.feedback_of(goal_handle)) >= 8,
        what="8 feedback messages",
    )
    assert probe.feedback_of(goal_handle) == [fibonacci(step) for step in range(1, 9)]


def test_bad_orders_are_rejected_and_the_server_carries_on(start_server, probe, capfd):
    start_server(FAST)
    for order in (-1, MAX_ORDER + 1, INT32_MAX, -(2**31)):
        goal_handle, _ = probe.send(order)
        assert not goal_handle.accepted, f"order {order} was accepted"
    log = capfd.readouterr().err
    assert f"Rejected goal of order -1: the order must be 0 to {MAX_ORDER}" in log
    assert f"Rejected goal of order {MAX_ORDER + 1}" in log

    goal_handle, _ = probe.send(MAX_ORDER)
    status, sequence = probe.result(goal_handle)
    assert status == GoalStatus.STATUS_SUCCEEDED
    assert sequence[-1] == 1836311903 and len(sequence) == MAX_ORDER + 2


def test_order_zero_returns_the_seeds(start_server, probe):
    start_server(FOREVER)  # no step at all, so no wait either
    goal_handle, feedback = probe.send(0)
    assert probe.result(goal_handle) == (GoalStatus.STATUS_SUCCEEDED, [0, 1])
    assert feedback == []


def test_cancel_stops_the_goal_within_the_step(start_server, probe, capfd):
    start_server(FOREVER)
    goal_handle, feedback = probe.send(5)
    spin_until(probe.executor, lambda: bool(feedback), what="the first feedback")

    cancel = goal_handle.cancel_goal_async()
    spin_until(probe.executor, cancel.done, what="the answer to the cancel request")
    assert len(cancel.result().goals_canceling) == 1, "cancel request refused"

    assert probe.result(goal_handle) == (GoalStatus.STATUS_CANCELED, [0, 1, 1])
    assert "ros_tutorial_action: Canceled" in capfd.readouterr().err


def test_new_goal_preempts_the_running_one(start_server, probe, capfd):
    start_server(FOREVER)
    first, feedback = probe.send(5)
    spin_until(probe.executor, lambda: bool(feedback), what="the first goal's first feedback")

    second, _ = probe.send(0)
    assert second.accepted

    assert probe.result(first) == (GoalStatus.STATUS_ABORTED, [0, 1, 1])
    assert probe.result(second) == (GoalStatus.STATUS_SUCCEEDED, [0, 1])
    assert "ros_tutorial_action: Preempted" in capfd.readouterr().err


# --- the client CLI, as a real process ---------------------------------------------------


def test_client_computes_the_books_order_20_by_default(start_server, node_process):
    # The last feedback must reach the client before the result: rclpy drops feedback that
    # comes after it. At FAST steps (10 ms apart) a loaded machine could deliver them out of
    # order once in a few hundred runs; 50 ms steps leave DDS five times the margin.
    start_server(0.05)
    client = node_process(*CLIENT)
    assert client.wait() == 0, client.output
    out = client.output
    assert "Waiting for action server to start." in out
    assert "Action server started, sending goal." in out
    assert f"Result: {fibonacci(20)}" in out
    assert "Action finished: SUCCEEDED" in out
    # Feedback (a topic) and the result (a service) travel apart: the client may get the
    # result, and end, before the last feedback messages are handled. What it prints is the
    # sequence growing step by step, in order.
    feedback = [
        ast.literal_eval(line.split("Received feedback: ")[1])
        for line in out.splitlines()
        if "Received feedback: " in line
    ]
    assert feedback, "no feedback printed"
    assert all(sequence == fibonacci(20)[: len(sequence)] for sequence in feedback), feedback
    lengths = [len(sequence) for sequence in feedback]
    assert lengths == sorted(set(lengths)), f"feedback out of order or repeated: {lengths}"


@pytest.mark.parametrize(
    "args",
    [["abc"], ["1", "2"], ["1.5"], ["2147483648"], ["--timeout", "x"], ["--timeout", "nan"]],
)
def test_client_usage_errors(node_process, args):
    client = node_process(*CLIENT, *args)
    assert client.wait() == 2
    assert "usage: action_client" in client.output
    assert "Traceback" not in client.output


def test_client_without_server_gives_up(node_process):
    client = node_process(*CLIENT, "3", "--timeout", "1")
    assert client.wait() == 1
    assert f"Action server {ACTION_NAME} not available after 1 s" in client.output
    assert "Traceback" not in client.output


def test_client_reports_a_rejected_goal(start_server, node_process):
    start_server(FAST)
    client = node_process(*CLIENT, str(MAX_ORDER + 1))
    assert client.wait() == 1
    assert f"Goal of order {MAX_ORDER + 1} rejected" in client.output


def test_ctrl_c_on_client_exits_130_without_a_traceback(start_server, node_process):
    start_server(FOREVER)
    client = node_process(*CLIENT, "5")
    client.wait_for_output(
        lambda lines: any("Received feedback: [0, 1, 1]" in line for line in lines),
        what="the first feedback",
    )
    assert client.interrupt() == 130
    assert "Traceback" not in client.output


def test_client_gives_up_after_its_timeout_with_the_books_line(start_server, node_process):
    start_server(FOREVER)
    client = node_process(*CLIENT, "5", "--timeout", "8")
    assert client.wait() == 1
    assert "Action did not finish before the time out." in client.output
    assert "Traceback" not in client.output


# The server's lines: all its output is its log (stdout stays empty), and a stop mid-goal adds
# nothing to it: no error of rclpy's about the goal's thread using ROS after the signal's
# shutdown (the start handles those: ros_tutorials_common/lesson_scripts.py).
SERVER_LINE = re.compile(r"\[(INFO|WARN)\] \[\d+\.\d+\] \[action_server\]: ros_tutorial_action: ")
SERVER_STARTS = {
    "console script": (str(BIN / "action_server"),),
    "ros2 run": (str(BIN / "ros2"), "run", "ros_tutorials_action", "action_server"),
}


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM], ids=["ctrl-c", "sigterm"])
@pytest.mark.parametrize("start", SERVER_STARTS)
@pytest.mark.parametrize("step_period", [FOREVER, 0.2], ids=["mid-step", "steps"])
def test_a_stop_mid_goal_ends_the_server_with_0_and_only_its_log_lines(
    node_process, loaded, signum, start, step_period
):
    """Ctrl-C or SIGTERM while a goal runs (in its step's wait, or between steps of 0.2 s):
    the server ends with status 0 and prints only its own lines, and its client gets no
    result. Under CPU load, where rclpy's signal handler shuts ROS down while the goal's
    thread still uses it."""
    server = node_process(*SERVER_STARTS[start], "--ros-args", "-p", f"step_period:={step_period}")
    client = node_process(*CLIENT, str(MAX_ORDER), "--timeout", "20")
    client.wait_for_output(
        lambda lines: any("Received feedback: [0, 1, 1]" in line for line in lines),
        what="the first feedback",
    )
    server.process.send_signal(signum)
    assert server.wait() == 0, server.output
    assert all(SERVER_LINE.match(line) for line in server.lines), server.output
    assert "Result:" not in client.output


@pytest.fixture
def loaded() -> Iterator[None]:
    """Every core kept busy by two processes while the test runs."""
    load = CpuLoad(2 * (os.cpu_count() or 1), nice=0, limit=TIMEOUT * 4)
    load.start()
    try:
        yield
    finally:
        load.stop()
