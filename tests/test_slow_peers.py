"""A node that never answers (its one thread stuck in a callback) among nodes that do: the
tools print what answered, name what did not, and exit 1. A stuck node made `rosparam list`
print nothing; `rqt_logger_level` printed nothing when no node serves logger levels."""

from __future__ import annotations

import pytest
from helpers import NodeProcess, run

STUCK = """
import time, rclpy
from rclpy.node import Node
rclpy.init()
node = Node("stuck")
node.declare_parameter("never_seen", 1)
node.create_timer(0.2, lambda: time.sleep(3600))  # its only thread never serves again
print("stuck soon", flush=True)
rclpy.spin(node)
"""


@pytest.fixture
def stuck_and_talker(own_domain, node_process):
    stuck = node_process("-c", STUCK)
    stuck.wait_for_text("stuck soon")
    talker: NodeProcess = node_process("-m", "ros_tutorials_topic.talker")
    talker.wait_for_text("hello world 1")
    return stuck, talker


@pytest.mark.parametrize(
    ("command", "answered"),
    [
        (("rosparam", "list"), "/talker/use_sim_time"),
        (("ros2", "param", "list"), "/talker:\n  start_type_description_service"),
        (("rosparam", "dump"), "/talker:\n  ros__parameters:"),
    ],
)
def test_what_answered_is_printed_and_the_silent_node_named(stuck_and_talker, command, answered):
    result = run(*command, "--timeout", "8")  # the talker answers at once, even under load
    assert result.returncode == 1, result.stdout + result.stderr
    assert answered in result.stdout
    assert "never_seen" not in result.stdout
    lines = result.stderr.strip().splitlines()
    assert lines == [
        "error: no answer from node '/stuck' within 8 s: its parameters are missing above"
    ], result.stderr


def test_rqt_logger_level_says_when_no_node_runs(own_domain):
    """Nodes that serve no logger levels are listed with why (tests/test_console.py); with
    no node at all, one line."""
    result = run("rqt_logger_level")
    assert result.returncode == 1 and not result.stdout
    assert result.stderr == "error: no running node (rqt_logger_level lists the running nodes)\n"
