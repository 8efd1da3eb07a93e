"""The action server under a storm of requests: every request it takes is answered, every
accepted goal gets a result; a request it never answers fails on the client's side, in time.

The server queues up to 1000 requests per service (REQUESTS in the server; rclpy's default is
10, and the rest were lost). The probe's own queues must be as deep: rclpy's ActionClient
keeps 10 responses by default, and a client that sends 100 goals at once would lose the others.
"""

from __future__ import annotations

import threading

import pytest
from action_msgs.msg import GoalStatus
from helpers import spin_until
from rclpy.action import ActionClient, ActionServer
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import QoSProfile
from ros_tutorials_interfaces.action import Fibonacci
from test_action import stop_server

from ros_tutorials_action.server import ACTION_NAME, REQUESTS, FibonacciActionServer

GOALS = 100
CANCELS = 400
STORM_TIMEOUT = 120.0  # generous: a loaded 2-core machine; the waits end as soon as all is in
DEEP = QoSProfile(depth=1000)


@pytest.fixture
def server(context):
    """The action server in this process, spun by its own executor thread."""
    node = FibonacciActionServer(
        context=context, parameter_overrides=[Parameter("step_period", value=3600.0)]
    )
    executor = MultiThreadedExecutor(num_threads=4, context=context)
    executor.add_node(node)
    stop = threading.Event()
    thread = threading.Thread(
        target=lambda: [executor.spin_once(timeout_sec=0.1) for _ in iter(stop.is_set, True)],
        daemon=True,
    )
    thread.start()
    yield node
    stop_server(node, executor, stop, thread)


@pytest.fixture
def deep_client(context, executor):
    node = Node("storm_probe", context=context)
    executor.add_node(node)
    client = ActionClient(
        node, Fibonacci, ACTION_NAME, goal_service_qos_profile=DEEP,
        result_service_qos_profile=DEEP, cancel_service_qos_profile=DEEP,
    )  # fmt: skip
    spin_until(executor, client.server_is_ready, what="the action server")
    yield client
    client.destroy()  # destroy_node() alone leaves a node with an action client in the graph


def test_the_server_queues_more_requests_than_rclpys_default():
    assert REQUESTS.depth >= max(GOALS, CANCELS)


def test_every_goal_of_a_storm_is_answered_and_every_accepted_goal_gets_a_result(
    server, deep_client, executor
):
    sent = [deep_client.send_goal_async(Fibonacci.Goal(order=3)) for _ in range(GOALS)]
    spin_until(
        executor, lambda: all(f.done() for f in sent), STORM_TIMEOUT, f"answers to {GOALS} goals"
    )
    goals = [f.result() for f in sent]
    assert all(goal.accepted for goal in goals)

    results = [goal.get_result_async() for goal in goals]
    # Each new goal preempts the one before; the last one runs (an hour per step): cancel it.
    spin_until(
        executor,
        lambda: sum(not r.done() for r in results) <= 1,
        STORM_TIMEOUT,
        f"the results of {GOALS - 1} preempted goals",
    )
    running = [goal for goal, result in zip(goals, results, strict=True) if not result.done()]
    for goal in running:
        goal.cancel_goal_async()
    spin_until(
        executor, lambda: all(r.done() for r in results), STORM_TIMEOUT, "the last goal's result"
    )
    statuses = [r.result().status for r in results]
    assert statuses.count(GoalStatus.STATUS_ABORTED) >= GOALS - 1  # preempted
    assert set(statuses) <= {GoalStatus.STATUS_ABORTED, GoalStatus.STATUS_CANCELED}


def test_every_cancel_request_of_a_storm_is_answered(server, deep_client, executor):
    sent = deep_client.send_goal_async(Fibonacci.Goal(order=5))
    spin_until(executor, sent.done, what="the answer to the goal")
    goal = sent.result()
    assert goal.accepted

    cancels = [goal.cancel_goal_async() for _ in range(CANCELS)]
    spin_until(
        executor,
        lambda: all(c.done() for c in cancels),
        STORM_TIMEOUT,
        f"answers to {CANCELS} cancel requests",
    )
    assert any(c.result().goals_canceling for c in cancels)
    result = goal.get_result_async()
    spin_until(executor, result.done, what="the canceled goal's result")
    assert result.result().status == GoalStatus.STATUS_CANCELED


def test_a_goal_the_server_never_answers_fails_on_the_clients_side(context, node_process):
    # An action server nobody spins: it is in the graph, it takes no request (as one whose
    # queue is full would not): the client must give up after --timeout, with a message.
    node = Node("action_server", context=context)
    server = ActionServer(node, Fibonacci, ACTION_NAME, lambda goal_handle: Fibonacci.Result())
    try:
        client = node_process("-m", "ros_tutorials_action.client", "3", "--timeout", "3")
        assert client.wait() == 1
        assert f"No answer from action server {ACTION_NAME} to the goal" in client.output
        assert "Traceback" not in client.output
    finally:
        server.destroy()
        node.destroy_node()
