"""The parameter lesson: calculation_method changed through the real parameter services
(as ``ros2 param set`` does), given at start, refused when invalid; the dynamics talker."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import spin_until
from rclpy.node import Node
from rclpy.parameter import Parameter, parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient
from ros_tutorials_interfaces.srv import SrvTutorial
from std_msgs.msg import String

import ros_tutorials_parameter
from ros_tutorials_parameter.server import ServiceServerWithParameter
from ros_tutorials_parameter.talker import DynamicsTalker

INT64_MIN, INT64_MAX = -(2**63), 2**63 - 1

PARAMS_FILE = Path(ros_tutorials_parameter.__file__).parent / "config" / "parameters.yaml"


class Probe:
    """A test node that calls ros_tutorial_srv and sets service_server's parameters."""

    def __init__(self, context, executor, target: str = "service_server") -> None:
        self.node = Node("probe", context=context)
        executor.add_node(self.node)
        self.executor = executor
        self.client = self.node.create_client(SrvTutorial, "ros_tutorial_srv")
        self.parameters = AsyncParameterClient(self.node, target)

    def call(self, a: int, b: int) -> int:
        spin_until(self.executor, self.client.service_is_ready, what="service ros_tutorial_srv")
        future = self.client.call_async(SrvTutorial.Request(a=a, b=b))
        spin_until(self.executor, future.done, what=f"the answer to {a}, {b}")
        return future.result().result

    def set(self, name: str, value):
        """Set one parameter through the node's set_parameters service; return its result."""
        spin_until(self.executor, self.parameters.services_are_ready, what="parameter services")
        future = self.parameters.set_parameters([Parameter(name, value=value)])
        spin_until(self.executor, future.done, what=f"set_parameters {name}={value!r}")
        return future.result().results[0]

    def get(self, name: str):
        spin_until(self.executor, self.parameters.services_are_ready, what="parameter services")
        future = self.parameters.get_parameters([name])
        spin_until(self.executor, future.done, what=f"get_parameters {name}")
        return parameter_value_to_python(future.result().values[0])


@pytest.fixture
def server_and_probe(context, executor):
    server = ServiceServerWithParameter(context=context)
    executor.add_node(server)
    return server, Probe(context, executor)


def test_book_vectors_after_run_time_changes(server_and_probe, capfd):
    _, probe = server_and_probe
    assert probe.call(10, 5) == 15  # default: 1, plus
    results = {}
    for method in (2, 3, 4, 1):
        outcome = probe.set("calculation_method", method)
        assert outcome.successful, outcome.reason
        results[method] = probe.call(10, 5)
    assert results == {2: 5, 3: 50, 4: 2, 1: 15}

    log = capfd.readouterr().err
    assert "[service_server]: request: x=10, y=5" in log
    assert "[service_server]: sending back response: [50]" in log


def test_division_by_zero_and_rounding_toward_zero(server_and_probe, capfd):
    _, probe = server_and_probe
    assert probe.set("calculation_method", 4).successful
    assert probe.call(7, 0) == 0
    assert probe.call(-7, 2) == -3, "integer division rounds toward zero as in C++"
    assert probe.call(7, -2) == -3
    assert probe.call(-8, -2) == 4
    log = capfd.readouterr().err
    assert "[WARN]" in log and "division by zero (7 / 0); sending back 0" in log


@pytest.mark.parametrize(
    ("method", "a", "b", "expression"),
    [
        (1, INT64_MAX, 1, f"{INT64_MAX} + 1"),
        (2, INT64_MIN, 1, f"{INT64_MIN} - 1"),
        (3, INT64_MAX, 2, f"{INT64_MAX} * 2"),
        (3, INT64_MIN, -1, f"{INT64_MIN} * -1"),
        (4, INT64_MIN, -1, f"{INT64_MIN} / -1"),
    ],
)
def test_int64_overflow_answers_0_and_the_server_keeps_serving(
    server_and_probe, capfd, method, a, b, expression
):
    _, probe = server_and_probe
    assert probe.set("calculation_method", method).successful
    assert probe.call(a, b) == 0
    assert probe.call(10, 5) == {1: 15, 2: 5, 3: 50, 4: 2}[method], "server stopped answering"
    log = capfd.readouterr().err
    assert f"{expression} = " in log and "does not fit in int64; sending back 0" in log


@pytest.mark.parametrize(
    ("value", "reason"),
    [
        (0, "out of range"),
        (5, "out of range"),
        (-1, "out of range"),
        ("two", "Wrong parameter type"),
        (2.0, "Wrong parameter type"),
        (True, "Wrong parameter type"),
    ],
)
def test_refused_values_leave_the_behaviour_unchanged(server_and_probe, value, reason):
    _, probe = server_and_probe
    assert probe.set("calculation_method", 3).successful
    outcome = probe.set("calculation_method", value)
    assert not outcome.successful
    assert reason in outcome.reason
    assert probe.get("calculation_method") == 3
    assert probe.call(10, 5) == 50


@pytest.mark.parametrize(
    ("ros_args", "expected"),
    [
        (["-p", "calculation_method:=2"], 5),
        (["--params-file", str(PARAMS_FILE)], 50),  # the file says 3
    ],
)
def test_parameter_given_at_start(node_process, context, executor, ros_args, expected):
    server = node_process("-m", "ros_tutorials_parameter.server", "--ros-args", *ros_args)
    probe = Probe(context, executor)
    assert probe.call(10, 5) == expected
    assert server.interrupt() == 0, server.output


@pytest.mark.parametrize(
    "value", ["calculation_method:=7", "calculation_method:=two", "calculation_method:=1.5"]
)
def test_invalid_parameter_at_start_is_a_clear_error(node_process, value):
    server = node_process("-m", "ros_tutorials_parameter.server", "--ros-args", "-p", value)
    assert server.wait() != 0
    assert "error: " in server.output and "calculation_method" in server.output
    assert "Traceback" not in server.output


def test_client_with_parameter_calls_the_server(node_process):
    server = node_process(
        "-m", "ros_tutorials_parameter.server", "--ros-args", "-p", "calculation_method:=3"
    )
    server.wait_for_output(lambda lines: any("ready srv server!" in x for x in lines))
    client = node_process("-m", "ros_tutorials_parameter.client", "10", "5", "--timeout", "60")
    assert client.wait(90) == 0, client.output
    assert "[service_client]: receive srv, srv.Response.result: 50" in client.output
    assert server.interrupt() == 0, server.output


def test_dynamics_talker_follows_talker_str(context, executor):
    talker = DynamicsTalker(context=context)
    executor.add_node(talker)
    probe = Probe(context, executor, target="dynamics_talker")
    heard: list[str] = []
    probe.node.create_subscription(String, "chatter", lambda msg: heard.append(msg.data), 10)

    spin_until(executor, lambda: "hello world" in heard, what="'hello world' on chatter")
    outcome = probe.set("talker_str", "Goodbye")
    assert outcome.successful, outcome.reason
    spin_until(executor, lambda: heard[-1:] == ["Goodbye"], what="'Goodbye' on chatter")

    assert not probe.set("talker_str", 42).successful, "a number is not a talker_str"
    count = len(heard)
    spin_until(executor, lambda: len(heard) >= count + 3, what="more messages")
    assert set(heard[count:]) == {"Goodbye"}
