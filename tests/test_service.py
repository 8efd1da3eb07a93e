"""The service lesson: servers in-process, client command lines as real processes."""

from __future__ import annotations

import importlib

import pytest
from helpers import run, spin_until
from rclpy.node import Node
from ros_tutorials_interfaces.srv import AddTwoInts, SrvTutorial

from ros_tutorials_service.add_two_ints_server import AddTwoIntsServer
from ros_tutorials_service.server import ServiceServer

INT64_MIN, INT64_MAX = -(2**63), 2**63 - 1

# (client module, the service it calls)
CLIENTS = [
    ("ros_tutorials_service.client", "ros_tutorial_srv"),
    ("ros_tutorials_parameter.client", "ros_tutorial_srv"),
    ("ros_tutorials_service.add_two_ints_client", "add_two_ints"),
]


def call(executor, client, a: int, b: int):
    """Send one request through client and return the response, spinning until it comes."""
    spin_until(executor, client.service_is_ready, what=f"service {client.srv_name}")
    future = client.call_async(client.srv_type.Request(a=a, b=b))
    spin_until(executor, future.done, what=f"the answer of {client.srv_name} to {a}, {b}")
    return future.result()


@pytest.fixture
def serving(context, executor):
    """serving(ServerClass, srv_type, name): the lesson's server in-process, and a client of
    its service on a probe node, both spun by the test's executor."""

    def start(server_class, srv_type, service: str):
        probe = Node("probe", context=context)
        for node in (server_class(context=context), probe):
            executor.add_node(node)
        return probe.create_client(srv_type, service)

    return start


def test_service_server_adds_and_logs_like_the_book(executor, serving, capfd):
    client = serving(ServiceServer, SrvTutorial, "ros_tutorial_srv")

    assert call(executor, client, 2, 3).result == 5
    assert call(executor, client, -7, 3).result == -4

    log = capfd.readouterr().err
    assert "[service_server]: ready srv server!" in log
    assert "[service_server]: request: x=2, y=3" in log
    assert "[service_server]: sending back response: 5" in log


def test_service_server_answers_0_on_int64_overflow_and_keeps_serving(executor, serving, capfd):
    client = serving(ServiceServer, SrvTutorial, "ros_tutorial_srv")

    assert call(executor, client, INT64_MAX, 1).result == 0
    assert call(executor, client, INT64_MIN, -1).result == 0
    assert call(executor, client, INT64_MAX, INT64_MIN).result == -1
    assert call(executor, client, 2, 3).result == 5, "the server stopped answering"

    log = capfd.readouterr().err
    assert "[WARN]" in log and f"{INT64_MAX} + 1 = {INT64_MAX + 1} does not fit in int64" in log
    assert f"{INT64_MIN} + -1 = {INT64_MIN - 1} does not fit in int64" in log


def test_add_two_ints_round_trip(executor, serving, capfd):
    client = serving(AddTwoIntsServer, AddTwoInts, "add_two_ints")

    assert call(executor, client, 1, 2).sum == 3
    assert call(executor, client, INT64_MAX, INT64_MAX).sum == 0
    assert call(executor, client, -40, 2).sum == -38

    log = capfd.readouterr().err
    assert "[add_two_ints_server]: Ready to add two ints." in log
    assert "[add_two_ints_server]: request: x=1, y=2" in log
    assert "[add_two_ints_server]: sending back response: [3]" in log


def test_service_client_calls_the_server(node_process):
    server = node_process("-m", "ros_tutorials_service.server")
    server.wait_for_output(lambda lines: any("ready srv server!" in x for x in lines))
    client = node_process("-m", "ros_tutorials_service.client", "2", "3", "--timeout", "60")

    assert client.wait(90) == 0, client.output
    assert "[service_client]: send srv, srv.Request.a and b: 2, 3" in client.output
    assert "[service_client]: receive srv, srv.Response.result: 5" in client.output
    server.wait_for_output(lambda lines: any("sending back response: 5" in x for x in lines))
    assert server.interrupt() == 0, server.output


def test_add_two_ints_client_calls_the_server(node_process):
    server = node_process("-m", "ros_tutorials_service.add_two_ints_server")
    client = node_process(
        "-m", "ros_tutorials_service.add_two_ints_client", "--timeout", "60", "-5", "12"
    )

    assert client.wait(90) == 0, client.output
    assert "[add_two_ints_client]: Sum: 7" in client.output
    assert server.interrupt() == 0, server.output


@pytest.mark.parametrize("module", [module for module, _ in CLIENTS])
@pytest.mark.parametrize(
    ("args", "complaint"),
    [
        ([], "the following arguments are required"),
        (["1"], "the following arguments are required"),
        (["1", "2", "3"], "unrecognized arguments: 3"),
        (["1.5", "2"], "invalid int value: '1.5'"),
        (["1", "two"], "invalid int value: 'two'"),
        (["1", "2", "--timeout", "x"], "invalid float value: 'x'"),
        # rclpy's own failure for a number int64 cannot hold is a SystemError traceback.
        (["9223372036854775808", "0"], "must fit in int64"),
        # rclpy's own failure for a wait it cannot make is a traceback too.
        (["1", "2", "--timeout", "nan"], "--timeout must be more than 0"),
        (["1", "2", "--timeout", "-1"], "--timeout must be more than 0"),
        (["1", "2", "--timeout", "1e10"], "at most 3600 seconds"),
    ],
)
def test_client_usage_errors(capsys, module, args, complaint):
    # In this process: the arguments are read before anything of ROS starts, and a process
    # per case (42) costs a second of CPU each; the clients as processes are tested above
    # and below. Anything but argparse's exit (a traceback in a process) fails the test.
    with pytest.raises(SystemExit) as exited:
        importlib.import_module(module).main([module, *args])
    assert exited.value.code == 2
    output = capsys.readouterr()
    assert output.out == ""
    assert "usage: " in output.err
    assert complaint in output.err


@pytest.mark.parametrize(
    ("package", "executable"),
    [
        ("ros_tutorials_service", "service_client"),
        ("ros_tutorials_parameter", "service_client_with_parameter"),
        ("ros_tutorials_service", "add_two_ints_client"),
        ("ros_tutorials_action", "action_client"),
    ],
)
def test_ros2_run_refuses_malformed_ros_arguments_in_one_line(package, executable):
    # The lesson is plain rclpy (rcl's own error and rclpy's traceback, as any ROS 2 node);
    # `ros2 run` checks the ROS arguments before it starts it.
    result = run("ros2", "run", package, executable, "1", "2", "--ros-args", "-r", "bad")
    assert result.returncode == 1
    assert result.stderr.startswith("error: invalid ROS arguments: Couldn't parse remap rule")
    assert result.stderr.count("\n") == 1 and result.stdout == ""


@pytest.mark.parametrize(("module", "service"), CLIENTS)
def test_client_without_server_fails_clearly(node_process, module, service):
    # The test session's ROS domain is private: no server exists.
    client = node_process("-m", module, "1", "2", "--timeout", "1.5")
    assert client.wait() == 1
    assert f"Failed to call service {service}: no server within 1.5 s" in client.output
    assert "Traceback" not in client.output


def test_client_interrupted_while_waiting_exits_cleanly(node_process, context, executor):
    client = node_process("-m", "ros_tutorials_service.client", "1", "2", "--timeout", "120")
    probe = Node("probe", context=context)
    executor.add_node(probe)
    # The client's node in the graph: it waits for the server (it says nothing while it does).
    spin_until(executor, lambda: "service_client" in probe.get_node_names(), what="the client")
    assert client.interrupt() == 130
    assert "Traceback" not in client.output
