"""What learners run into with ros2 and its ROS 1 spellings, and what they see then.

Two message types on one topic (the AandB talker beside the String listener, both on
/chatter), two nodes of one name, values YAML reads as text, a closed pipe, a call without
its values, and ROS 1's `rostopic echo /topic/field`. Every command is the installed
console script, as a learner types it.
"""

from __future__ import annotations

import os
import subprocess

import pytest
from helpers import BIN, fails, ok, spin_until
from helpers import run as tool
from rclpy.node import Node

AANDB = "ros_tutorials_interfaces/AandB"


def _in_graph(executor, condition, what: str) -> None:
    """Wait until the graph, as a node of the test sees it, satisfies condition(node)."""
    probe = Node("rostool_test_probe", context=executor.context)
    executor.add_node(probe)
    spin_until(executor, lambda: condition(probe), what=what)


def _talker_nodes(node: Node) -> int:
    return [name for name, _ns in node.get_node_names_and_namespaces()].count("talker")


# Two types on one topic: the seed's AandB talker beside the lesson's String listener.


def test_two_types_on_one_topic_are_all_shown(executor, node_process):
    node_process("-m", "ros_tutorials_topic.aandb_talker")
    node_process("-m", "ros_tutorials_topic.listener")
    _in_graph(
        executor,
        lambda node: len(dict(node.get_topic_names_and_types()).get("/chatter", [])) == 2,
        "both types on /chatter",
    )
    info = ok("rostopic", "info", "/chatter", "--timeout", "30")
    lines = info.splitlines()
    assert "Type: ros_tutorials_interfaces/msg/AandB" in lines
    assert "Type: std_msgs/msg/String" in lines
    assert "different types do not talk to each other" in info
    assert "  Node: /talker" in lines and "  Node: /listener" in lines
    assert "Publisher count: 1" in lines and "Subscription count: 1" in lines
    # ros2's own: the list of types on one line, as ros2topic prints it.
    assert ok("ros2", "topic", "info", "/chatter").splitlines()[0] == (
        "Type: ['ros_tutorials_interfaces/msg/AandB', 'std_msgs/msg/String']"
    )
    # Publishing the talker's type reaches no one: the only subscriber wants a String.
    result = tool("rostopic", "pub", "-1", "/chatter", AANDB, "1", "2", "--timeout", "3")
    assert result.returncode == 0, result.stderr
    assert result.stderr.strip() == (
        "warning: /chatter carries std_msgs/msg/String, not ros_tutorials_interfaces/msg/AandB: "
        "the message will not reach its subscribers; publishing anyway"
    )


# Two nodes of one name: the tools say so, as ros2's do.


def test_two_nodes_of_one_name_are_pointed_out(executor, node_process):
    node_process("-m", "ros_tutorials_topic.talker")
    node_process("-m", "ros_tutorials_topic.talker")
    _in_graph(executor, lambda node: _talker_nodes(node) == 2, "two /talker nodes")
    listed = tool("rosnode", "list")
    assert listed.returncode == 0 and listed.stdout.split().count("/talker") == 2
    assert "nodes in the graph that share an exact name" in listed.stderr
    info = tool("rosnode", "info", "/talker")
    assert info.returncode == 0 and info.stdout.startswith("/talker\n")
    assert 'There are 2 nodes in the graph with the exact name "/talker"' in info.stderr


# ROS 1's `rostopic echo /topic/field`.


def test_rostopic_echo_of_a_field(node_process):
    node_process("-m", "ros_tutorials_topic.publisher").wait_for_text("send msg")
    data = ok("rostopic", "echo", "/ros_tutorial_msg/data", "-n", "1", "--timeout", "30")
    assert data.splitlines()[1] == "---" and int(data.splitlines()[0]) > 0
    sec = ok("rostopic", "echo", "/ros_tutorial_msg/stamp/sec", "-n", "1", "--timeout", "30")
    assert int(sec.splitlines()[0]) > 0
    line = fails("rostopic", "echo", "/ros_tutorial_msg/nope", "-n", "1", "--timeout", "30")
    assert line == "error: ros_tutorials_interfaces/msg/MsgTutorial has no field 'nope'"
    line = fails("ros2", "topic", "echo", "/ros_tutorial_msg", "--field", "stamp.x", "--once")
    assert line == (
        "error: Invalid field 'stamp.x': builtin_interfaces/msg/Time has no field 'x' "
        "(fields: sec, nanosec)"
    )


# Values: a float field takes what Python's float() reads (YAML 1.1 reads 1e40 as text).


@pytest.mark.parametrize("values", [("{a: 1e40, b: 2}",), ("1e40", "2")])
def test_a_float_written_without_a_dot_is_range_checked(values):
    line = fails("rostopic", "pub", "-1", "/t", AANDB, *values, "--timeout", "1")
    assert "a = 1e+40 is out of range for float32" in line


def test_a_float_written_without_a_dot_is_sent(node_process):
    listener = node_process("-m", "ros_tutorials_topic.aandb_listener")
    ok("rostopic", "pub", "-1", "/chatter", AANDB, "1e-3", "2", "--timeout", "30")
    listener.wait_for_text("I heard: msg:a 0.001000, msg:b 2.000000")
    assert "a is a number" in fails("rostopic", "pub", "-1", "/t", AANDB, "x", "2")


# A closed pipe (`rospack list | head`): every tool that prints leaves quietly.


@pytest.mark.parametrize(
    "args",
    [
        ("rospack", "list"),
        ("rospack", "find", "std_msgs"),
        ("rosrun", "-h"),
        ("roscore",),
        ("rosmsg", "list"),
        ("ros2", "interface", "list"),
        ("roslaunch", "--print", "ros_tutorials_topic", "union.launch"),
        ("roslaunch", "--show-args", "ros_tutorials_topic", "union.launch"),
    ],
)
def test_a_closed_pipe_ends_a_tool_quietly(args):
    reader, writer = os.pipe()
    os.close(reader)  # the reader has gone before the tool prints: `| head` at its worst
    try:
        result = subprocess.run(
            [str(BIN / args[0]), *args[1:]],
            stdout=writer,
            stderr=subprocess.PIPE,
            text=True,
            timeout=60,
        )
    finally:
        os.close(writer)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""


# Services: ROS 1's rosservice call wants the request's values.


def test_rosservice_call_without_values_says_what_it_takes(node_process):
    node_process("-m", "ros_tutorials_service.server").wait_for_text("ready srv server!")
    line = fails("rosservice", "call", "/ros_tutorial_srv", "--timeout", "30")
    assert "takes 2 value(s) (a b), got 0" in line
    # ros2's spelling keeps its default: an empty request (a = b = 0).
    out = ok(
        "ros2",
        "service",
        "call",
        "/ros_tutorial_srv",
        "ros_tutorials_interfaces/srv/SrvTutorial",
    )
    assert "result=0" in out
