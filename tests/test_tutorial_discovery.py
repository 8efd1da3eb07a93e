"""The official Jazzy tutorial "Improved Dynamic Discovery" (Advanced), its same-host table, in
the cells that stay on loopback: `ros2 run demo_nodes_cpp talker` and `listener` with
ROS_AUTOMATIC_DISCOVERY_RANGE LOCALHOST or OFF, with and without ROS_STATIC_PEERS=127.0.0.1.
SUBNET is left out: Fast DDS would multicast beyond this machine."""

from __future__ import annotations

import pytest


def _run(node_process, executable: str, discovery: str, peers: str = "", *remap: str):
    env = {"ROS_AUTOMATIC_DISCOVERY_RANGE": discovery, "ROS_STATIC_PEERS": peers}
    args = ["--ros-args", "-r", f"chatter:={remap[0]}"] if remap else []
    return node_process("-m", "ros2cmd", "run", "demo_nodes_cpp", executable, *args, env=env)


@pytest.mark.parametrize(
    ("listener", "talker"),
    [
        (("LOCALHOST", ""), ("LOCALHOST", "")),
        (("LOCALHOST", "127.0.0.1"), ("LOCALHOST", "")),  # node A with a static peer
        (("LOCALHOST", ""), ("LOCALHOST", "127.0.0.1")),  # node B with one
    ],
)
def test_localhost_nodes_discover_each_other(node_process, listener, talker):  # the table's O
    _run(node_process, "talker", *talker)
    heard = _run(node_process, "listener", *listener)
    heard.wait_for_text("I heard: [Hello World: ", count=3)


@pytest.mark.parametrize(
    ("listener", "talker"),
    [
        (("OFF", ""), ("LOCALHOST", "")),
        (("LOCALHOST", ""), ("OFF", "")),
        (("OFF", "127.0.0.1"), ("LOCALHOST", "")),  # a static peer does not undo OFF
        (("LOCALHOST", "127.0.0.1"), ("OFF", "127.0.0.1")),
    ],
)
def test_a_node_with_discovery_off_meets_no_one(node_process, listener, talker):  # the table's X
    off_side = _run(node_process, "talker", *talker)
    unheard = _run(node_process, "listener", *listener)
    # The same pair, both LOCALHOST, started after them on another topic: once they have
    # discovered each other and passed three messages, the first pair had as long.
    _run(node_process, "talker", "LOCALHOST", "", "control")
    control = _run(node_process, "listener", "LOCALHOST", "", "control")
    control.wait_for_text("I heard: [Hello World: ", count=3)
    off_side.wait_for_text("Publishing: 'Hello World: ", count=3)
    assert "I heard" not in unheard.output, unheard.output
