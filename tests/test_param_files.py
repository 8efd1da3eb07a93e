"""Params files as ROS 2 reads them (`ros2 param load`, `rosparam load`), against real nodes.

Two parameter-lesson servers run: /service_server and /ns/service_server. A params file gives
a node every entry that matches its full name (``/ns/node`` or ``ns/node``, ``/**`` any node,
``/*`` one name part), in the file's order; an entry for another node, even one with the same
base name, gives it nothing. The last test checks this against what rclpy itself gives a node
started with ``--params-file``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest
from helpers import spin_until
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_client import AsyncParameterClient
from rclpy.task import Future
from test_ros2 import _ready, fails, ok

SERVERS = ("/service_server", "/ns/service_server")


@pytest.fixture
def two_servers(node_process):
    """The parameter lesson's server twice: in the root namespace and in /ns."""
    _ready(node_process("-m", "ros_tutorials_parameter.server"))
    _ready(node_process("-m", "ros_tutorials_parameter.server", "--ros-args", "-r", "__ns:=/ns"))


class Probe:
    """Reads and sets calculation_method in this process (quicker than a tool process)."""

    def __init__(self, context, executor) -> None:
        self.executor = executor
        self.node = Node("param_files_probe", context=context, start_parameter_services=False)
        executor.add_node(self.node)
        self.clients: dict[str, AsyncParameterClient] = {}

    def _call(self, server: str, request: Callable[[AsyncParameterClient], Future]) -> Any:
        if server not in self.clients:
            self.clients[server] = AsyncParameterClient(self.node, server)
        client = self.clients[server]
        spin_until(self.executor, client.services_are_ready, what=f"{server}'s parameters")
        future = request(client)
        spin_until(self.executor, future.done, what=f"{server}'s answer")
        return future.result()

    def get(self, server: str) -> int:
        response = self._call(server, lambda c: c.get_parameters(["calculation_method"]))
        return response.values[0].integer_value

    def set(self, server: str, value: int) -> None:
        parameter = Parameter("calculation_method", value=value)
        response = self._call(server, lambda c: c.set_parameters([parameter]))
        assert response.results[0].successful, response.results[0].reason


@pytest.fixture
def probe(context, executor) -> Probe:
    return Probe(context, executor)


def params_file(tmp_path, name: str, entries: dict[str, int]) -> str:
    path = tmp_path / name
    path.write_text(
        "".join(
            f"{key}:\n  ros__parameters:\n    calculation_method: {value}\n"
            for key, value in entries.items()
        )
    )
    return str(path)


def test_a_wildcard_file_sets_any_node(two_servers, probe, tmp_path):
    anyone = params_file(tmp_path, "any.yaml", {"/**": 3})
    for node in SERVERS:
        out = ok("ros2", "param", "load", node, anyone)
        assert out.strip() == "Set parameter calculation_method successful"
        assert probe.get(node) == 3
    # ROS 1's rosparam load needs nodes named in the file: '/**' alone names none.
    assert "names no node, only patterns such as '/**'" in fails("rosparam", "load", anyone)


def test_a_namespaced_entry_is_for_that_node_only(two_servers, probe, tmp_path):
    only_ns = params_file(tmp_path, "ns.yaml", {"/ns/service_server": 4})
    line = fails("ros2", "param", "load", "/service_server", only_ns)
    assert line == f"error: {only_ns} has no entry that matches /service_server"
    assert probe.get("/service_server") == 1  # untouched: the entry is /ns's
    ok("ros2", "param", "load", "/ns/service_server", only_ns)
    assert probe.get("/ns/service_server") == 4

    # Both forms of a full name (with and without the leading slash), after '/**': they win.
    mixed = params_file(
        tmp_path, "mixed.yaml", {"/**": 3, "ns/service_server": 2, "/service_server": 4}
    )
    ok("ros2", "param", "load", "/ns/service_server", mixed)
    assert probe.get("/ns/service_server") == 2
    ok("ros2", "param", "load", "/service_server", mixed)
    assert probe.get("/service_server") == 4

    # rosparam load: every node the file names gets the entries that match it.
    back = params_file(tmp_path, "back.yaml", {"/**": 3, "/service_server": 1})
    ok("rosparam", "load", back)
    assert probe.get("/service_server") == 1
    assert probe.get("/ns/service_server") == 2  # not named in the file: untouched


def test_an_entry_without_ros__parameters_is_refused_before_any_node_is_touched(
    node_process, probe, tmp_path
):
    _ready(node_process("-m", "ros_tutorials_parameter.server"))
    path = tmp_path / "flat.yaml"
    path.write_text("/**:\n  ros__parameters:\n    calculation_method: 3\n/ns/service_server: 4\n")
    line = fails("ros2", "param", "load", "/service_server", str(path))
    assert "'/ns/service_server' has no 'ros__parameters:' mapping" in line
    assert probe.get("/service_server") == 1


def test_describe_shows_the_declared_range(node_process):
    _ready(node_process("-m", "ros_tutorials_parameter.server", "--ros-args", "-r", "__ns:=/ns"))
    out = ok("ros2", "param", "describe", "/ns/service_server", "calculation_method")
    assert out.splitlines() == [
        "Parameter name: calculation_method",
        "  Type: integer",
        "  Description: operator: 1 plus, 2 minus, 3 multiplication, 4 division",
        "  Constraints:",
        "    Min value: 1",
        "    Max value: 4",
        "    Step: 1",
    ]
    line = fails("ros2", "param", "describe", "/ns/service_server", "nope")
    assert line == "error: node '/ns/service_server' has no parameter 'nope'"


def test_load_gives_a_node_what_it_takes_from_the_file_at_start(node_process, probe, tmp_path):
    """rcl's names ('/*' one part, '/**' any number, nested keys for namespaces), in the
    file's order, the later entry winning: the same as rclpy gives a node started with
    --params-file FILE."""
    path = tmp_path / "patterns.yaml"
    path.write_text(
        "ns:\n  service_server:\n    ros__parameters:\n      calculation_method: 4\n"
        + "/**/service_server:\n  ros__parameters:\n    calculation_method: 3\n"
        + "/*:\n  ros__parameters:\n    calculation_method: 2\n"
    )
    server = ("-m", "ros_tutorials_parameter.server", "--ros-args", "--params-file", str(path))
    _ready(node_process(*server))
    _ready(node_process(*server, "-r", "__ns:=/ns"))
    at_start = {node: probe.get(node) for node in SERVERS}
    assert at_start == {"/service_server": 2, "/ns/service_server": 3}
    for node in SERVERS:
        probe.set(node, 1)
        ok("ros2", "param", "load", node, str(path))
        assert probe.get(node) == at_start[node], node
