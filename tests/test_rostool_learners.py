"""What learners run into with rostool and its ROS 1 spellings, and what they see then.

Two message types on one topic (the AandB talker beside the String listener, both on
/chatter), two nodes of one name, values YAML reads as text, a closed pipe, a call without
its values, and ROS 1's `rostopic echo /topic/field`. Every command is the installed
console script, as a learner types it.
"""

from __future__ import annotations

import os
import subprocess

import pytest
from helpers import BIN, fails, ok

AANDB = "ros_tutorials_interfaces/AandB"


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
        ("rostool", "interface", "list"),
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
        "rostool",
        "service",
        "call",
        "/ros_tutorial_srv",
        "ros_tutorials_interfaces/srv/SrvTutorial",
    )
    assert "result=0" in out
