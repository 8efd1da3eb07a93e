"""The tests' warm starts (tests/warm.py) behave as cold starts do, and are used."""

from __future__ import annotations

import os
import sys

import helpers
import pytest
from helpers import BIN, NodeProcess, run


def test_project_commands_start_warm_and_others_cold(ros_domain):
    warm = helpers.warm
    assert warm is not None and warm.ready(), "the warm-start server did not start"
    assert warm.eligible([str(BIN / "rostopic"), "list"], os.environ)
    assert warm.eligible(["-m", "ros_tutorials_topic.publisher"], os.environ)
    assert warm.eligible(["-m", "ros2cmd", "topic", "list"], {**os.environ, "DISPLAY": ""})
    assert not warm.eligible(["-m", "launcher", "union.launch"], os.environ)
    assert not warm.eligible([str(BIN / "roslaunch"), "union.launch"], os.environ)
    assert not warm.eligible([str(BIN / "cmake"), "--version"], os.environ)
    assert not warm.eligible(["-c", "pass"], os.environ)
    other = {**os.environ, "AMENT_PREFIX_PATH": "/nonexistent"}
    assert not warm.eligible([str(BIN / "rostopic"), "list"], other)


@pytest.mark.parametrize(
    "args",
    [
        ["rostopic", "echo"],  # a usage error: argparse's message, exit 2
        ["rosmsg", "show", "std_msgs/String"],  # output, exit 0
        ["ros2", "interface", "show", "no_such_pkg/msg/Nope"],  # one error line, exit 1
    ],
)
def test_a_warm_command_prints_and_exits_as_a_cold_one(ros_domain, args):
    warm, cold = run(*args), run(*args, cold=True)
    assert (warm.returncode, warm.stdout, warm.stderr) == (
        cold.returncode,
        cold.stdout,
        cold.stderr,
    )


def test_standard_input_working_directory_and_argv_reach_the_command(ros_domain, tmp_path):
    (tmp_path / "params.yaml").write_text("/**:\n  ros__parameters:\n    x: 1\n")
    # rosmsg show without a type reads the type from a pipe (its standard input).
    shown = run("rosmsg", "show", input="std_msgs/String\n")
    assert shown.returncode == 0 and "string data" in shown.stdout, shown.stderr
    # A relative path is found in the working directory the test gave.
    missing = run("rosparam", "load", "nope.yaml", cwd=str(tmp_path))
    assert "nope.yaml" in missing.stderr and missing.returncode != 0


def test_a_warm_node_is_its_own_process_and_ends_by_ctrl_c_like_a_cold_one(ros_domain):
    ends, outputs = {}, {}
    for cold in (False, True):
        node = NodeProcess("-m", "ros_tutorials_topic.publisher", cold=cold)
        try:
            node.wait_for_text("send msg")
            assert node.process.pid not in (os.getpid(), os.getppid())
            assert sys.executable in node.args
            ends[cold] = (node.interrupt(), "Traceback" in node.output)
            outputs[cold] = node.output
        finally:
            node.kill()
    assert ends[False] == ends[True], f"{ends}\nwarm:\n{outputs[False]}\ncold:\n{outputs[True]}"
