"""Lists are complete for a node written with plain rclpy, not only for this project's nodes.

The learner's own node: `python -c` with only rclpy, started in an environment that has none
of this project's variables (so no Fast DDS profile: it announces itself every 3 s, not every
0.25 s), only ROS_DOMAIN_ID and ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST. `ros2 node list`,
`ros2 param list` and `ros2 node info` must show it in every run (they missed it in about 2
runs of 5: the wait for discovery ended after this project's announcement periods).
Through direct discovery (--no-daemon); test_daemon.py covers the daemon.
"""

from __future__ import annotations

import os

import pytest
from helpers import NodeProcess, at_once, ok

RUNS = 20
AT_ONCE = 5  # runs started together (each its own process and discovery)
PLAIN_NODE = """
import rclpy
from rclpy.node import Node

rclpy.init()
node = Node("plain_node")
print("plain node up", flush=True)
rclpy.spin(node)
"""


@pytest.fixture(scope="module")
def plain_node(ros_domain, tmp_path_factory):
    """The plain node, for the module: `env -i` leaves none of the suite's variables."""
    environment = [
        f"PATH={os.environ['PATH']}",
        f"HOME={tmp_path_factory.mktemp('home')}",  # rcl's log files go to ~/.ros/log
        f"ROS_DOMAIN_ID={ros_domain}",
        "ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST",
    ]
    node = NodeProcess("-c", PLAIN_NODE, prefix=("env", "-i", *environment))
    try:
        node.wait_for_text("plain node up")
        yield node
    finally:
        node.kill()


def _every_run(*command: str) -> list[str]:
    """The output of RUNS runs of a `ros2` command, AT_ONCE at a time."""
    outputs: list[str] = []
    for _ in range(0, RUNS, AT_ONCE):
        outputs += at_once(ok, *[("ros2", *command)] * AT_ONCE)
    return outputs


def _missed(outputs: list[str], seen: str) -> list[int]:
    return [run for run, output in enumerate(outputs) if seen not in output]


@pytest.mark.long  # 20 runs: 15 to 40 s
def test_node_list_shows_a_plain_node_every_time(plain_node):
    outputs = _every_run("node", "list", "--no-daemon")
    missed = _missed(outputs, "/plain_node\n")
    assert not missed, f"missed in runs {missed} of {RUNS}: {[outputs[run] for run in missed]}"


@pytest.mark.long  # 20 runs: 15 to 40 s
def test_param_list_shows_a_plain_node_every_time(plain_node):
    outputs = _every_run("param", "list", "--no-daemon")
    missed = [run for run, output in enumerate(outputs) if "  use_sim_time\n" not in output]
    missed = sorted({*missed, *_missed(outputs, "/plain_node:\n")})
    assert not missed, f"missed in runs {missed} of {RUNS}: {[outputs[run] for run in missed]}"


@pytest.mark.long  # 20 runs: 15 to 40 s
def test_node_info_shows_all_of_a_plain_node_every_time(plain_node):
    outputs = _every_run("node", "info", "/plain_node", "--no-daemon")
    for run, output in enumerate(outputs):
        # Its endpoints too: rcl's /rosout publisher and the parameter services.
        assert "    /rosout: rcl_interfaces/msg/Log\n" in output, (run, output)
        assert "    /plain_node/list_parameters: rcl_interfaces/srv/ListParameters\n" in output, (
            run,
            output,
        )


def test_the_plain_node_has_none_of_the_projects_variables(plain_node):
    """The test is what it says: the node runs without this project's Fast DDS profile."""
    with open(f"/proc/{plain_node.process.pid}/environ", "rb") as environ:
        names = {entry.split(b"=", 1)[0].decode() for entry in environ.read().split(b"\0") if entry}
    # (The wheels' rclpy sets its library path and starts again: those are its own.)
    assert "FASTRTPS_DEFAULT_PROFILES_FILE" not in names
    assert {name for name in names if name.startswith("ROS_")} == {
        "ROS_DOMAIN_ID",
        "ROS_AUTOMATIC_DISCOVERY_RANGE",
    }
