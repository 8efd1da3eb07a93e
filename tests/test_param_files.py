"""Params files as ROS 2 reads them (`rostool param load`, `rosparam load`), against real nodes.

Two parameter-lesson servers run: /service_server and /ns/service_server. A params file gives
a node its '/**' entry, then its own entry (``/ns/node`` or ``ns/node``), which wins; an entry
for another node, even one with the same base name, gives it nothing.
"""

from __future__ import annotations

from collections.abc import Callable

import pytest
from helpers import spin_until
from rclpy.node import Node
from rclpy.parameter_client import AsyncParameterClient
from test_rostool import _ready, fails, ok

SERVERS = ("/service_server", "/ns/service_server")


@pytest.fixture
def two_servers(node_process):
    """The parameter lesson's server twice: in the root namespace and in /ns."""
    _ready(node_process("-m", "ros_tutorials_parameter.server"))
    _ready(node_process("-m", "ros_tutorials_parameter.server", "--ros-args", "-r", "__ns:=/ns"))


@pytest.fixture
def method(context, executor) -> Callable[[str], int]:
    """A node's calculation_method, read in this process (quicker than a tool process)."""
    node = Node("param_files_probe", context=context, start_parameter_services=False)
    executor.add_node(node)
    clients: dict[str, AsyncParameterClient] = {}

    def read(server: str) -> int:
        client = clients.setdefault(server, AsyncParameterClient(node, server))
        spin_until(executor, client.services_are_ready, what=f"{server}'s parameter services")
        future = client.get_parameters(["calculation_method"])
        spin_until(executor, future.done, what=f"{server}'s answer")
        return future.result().values[0].integer_value

    return read


def params_file(tmp_path, name: str, entries: dict[str, int]) -> str:
    path = tmp_path / name
    path.write_text(
        "".join(
            f"{key}:\n  ros__parameters:\n    calculation_method: {value}\n"
            for key, value in entries.items()
        )
    )
    return str(path)


def test_a_wildcard_file_sets_any_node(two_servers, method, tmp_path):
    anyone = params_file(tmp_path, "any.yaml", {"/**": 3})
    for node in SERVERS:
        out = ok("rostool", "param", "load", node, anyone)
        assert out.strip() == "Set parameter calculation_method successful"
        assert method(node) == 3
    # ROS 1's rosparam load needs nodes named in the file: '/**' alone names none.
    assert "is for any node ('/**')" in fails("rosparam", "load", anyone)


def test_a_namespaced_entry_is_for_that_node_only_and_wins_over_the_wildcard(
    two_servers, method, tmp_path
):
    only_ns = params_file(tmp_path, "ns.yaml", {"/ns/service_server": 4})
    line = fails("rostool", "param", "load", "/service_server", only_ns)
    assert line == f"error: {only_ns} has no parameters for /service_server (nor for /**)"
    assert method("/service_server") == 1  # untouched: the entry is /ns's
    ok("rostool", "param", "load", "/ns/service_server", only_ns)
    assert method("/ns/service_server") == 4

    # Both forms of a full name (with and without the leading slash), after '/**'.
    mixed = params_file(
        tmp_path, "mixed.yaml", {"/**": 3, "ns/service_server": 2, "/service_server": 4}
    )
    ok("rostool", "param", "load", "/ns/service_server", mixed)
    assert method("/ns/service_server") == 2
    ok("rostool", "param", "load", "/service_server", mixed)
    assert method("/service_server") == 4

    # rosparam load: every node the file names gets '/**' and then its own entry.
    back = params_file(tmp_path, "back.yaml", {"/**": 3, "/service_server": 1})
    ok("rosparam", "load", back)
    assert method("/service_server") == 1
    assert method("/ns/service_server") == 2  # not named in the file: untouched


def test_an_entry_without_ros__parameters_is_refused_before_any_node_is_touched(
    node_process, method, tmp_path
):
    _ready(node_process("-m", "ros_tutorials_parameter.server"))
    path = tmp_path / "flat.yaml"
    path.write_text("/**:\n  ros__parameters:\n    calculation_method: 3\n/ns/service_server: 4\n")
    line = fails("rostool", "param", "load", "/service_server", str(path))
    assert "'/ns/service_server' has no 'ros__parameters:' mapping" in line
    assert method("/service_server") == 1


def test_describe_shows_the_declared_range(node_process):
    _ready(node_process("-m", "ros_tutorials_parameter.server", "--ros-args", "-r", "__ns:=/ns"))
    out = ok("rostool", "param", "describe", "/ns/service_server", "calculation_method")
    assert out.splitlines() == [
        "Parameter name: calculation_method",
        "  Type: integer",
        "  Description: operator: 1 plus, 2 minus, 3 multiplication, 4 division",
        "  Constraints:",
        "    Min value: 1",
        "    Max value: 4",
        "    Step: 1",
    ]
    line = fails("rostool", "param", "describe", "/ns/service_server", "nope")
    assert line == "error: node '/ns/service_server' has no parameter 'nope'"
