"""An environment rclpy.init cannot work with: one line naming the variable, exit status 1,
no traceback and no raw Fast DDS lines, from `ros2 run` (of a lesson, turtlesim), the tools,
the console scripts and the launcher."""

from __future__ import annotations

import os

import pytest
from helpers import run

COMMANDS = {
    # A lesson is plain rclpy: `ros2 run` checks the environment before it starts one.
    "ros2 run ros_tutorials_topic talker": ("ros2", "run", "ros_tutorials_topic", "talker"),
    "ros2 topic list": ("ros2", "topic", "list", "--no-daemon"),
    "rostopic list": ("rostopic", "list"),
    "turtlesim": ("ros2", "run", "turtlesim", "turtlesim_node"),
    # The launcher checks it once, before any of its nodes starts.
    "roslaunch": ("roslaunch", "ros_tutorials_topic", "union.launch"),
    "ros2 launch": ("ros2", "launch", "ros_tutorials_topic", "union.launch.xml"),
    "python -m launcher": ("python", "-m", "launcher", "union.launch"),
    # The console scripts: a lesson's (its wrapper checks as `ros2 run` does), turtlesim's.
    "talker": ("talker",),
    "turtlesim_node": ("turtlesim_node",),
}
PROBLEMS = {
    "domain id not a number": ({"ROS_DOMAIN_ID": "abc"}, "ROS_DOMAIN_ID='abc' is not a whole"),
    # rcl reads ASCII digits only; Python's int() would take these.
    "domain id in Arabic-Indic digits": (
        {"ROS_DOMAIN_ID": "\u0663"},
        "ROS_DOMAIN_ID='\u0663' is not a whole number in ASCII digits",
    ),
    "domain id in fullwidth digits": (
        {"ROS_DOMAIN_ID": "\uff11"},
        "ROS_DOMAIN_ID='\uff11' is not a whole number in ASCII digits",
    ),
    "domain id above Fast DDS's ports": ({"ROS_DOMAIN_ID": "300"}, "ROS_DOMAIN_ID='300' is above"),
    "log dir a file": (
        {"ROS_LOG_DIR": "/etc/passwd"},
        "cannot write ROS log files to '/etc/passwd' (ROS_LOG_DIR): not a directory",
    ),
    # rmw_fastrtps turns each peer into an IPv4 address when the first node is made.
    "static peer not an address": (
        {"ROS_STATIC_PEERS": "127.0.0.1;999.1.1.1"},
        "ROS_STATIC_PEERS: '999.1.1.1' is not an IP address or a host name",
    ),
    "static peer IPv6": (
        {"ROS_STATIC_PEERS": "::1"},
        "ROS_STATIC_PEERS: '::1' is an IPv6 address; Fast DDS takes IPv4 peers",
    ),
    "ROS_HOME where nothing can be made": (
        {"ROS_HOME": "/proc/no_such_process/ros"},
        "cannot write ROS log files to '/proc/no_such_process/ros/log' (ROS_HOME)",
    ),
}


@pytest.mark.parametrize("problem", PROBLEMS)
@pytest.mark.parametrize("name", COMMANDS)
def test_one_line_names_the_variable(name: str, problem: str):
    variables, expected = PROBLEMS[problem]
    env = {k: v for k, v in os.environ.items() if k not in ("ROS_LOG_DIR", "ROS_HOME")}
    result = run(*COMMANDS[name], env=env | variables, timeout=60)
    assert result.returncode == 1, f"{name}: status {result.returncode}\n{result.stderr}"
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and expected in lines[0], (
        result.stderr
    )
    assert "\x1b[" not in result.stderr  # no coloured Fast DDS lines
