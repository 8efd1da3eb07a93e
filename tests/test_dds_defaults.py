"""The DDS defaults reach every process this project starts, and a user's choice wins."""

from __future__ import annotations

import os
import subprocess
import sys

from helpers import TIMEOUT

from ros_tutorials_common.dds import DDS_DEFAULTS, apply_dds_defaults


def env_without_dds_defaults() -> dict[str, str]:
    env = dict(os.environ)
    for name in DDS_DEFAULTS:
        env.pop(name, None)
    return env


def test_defaults_fill_in_only_what_the_user_has_not_set():
    env = apply_dds_defaults({"ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET"})
    assert env["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "SUBNET"
    assert env["FASTRTPS_DEFAULT_PROFILES_FILE"].endswith("fastdds.xml")
    assert apply_dds_defaults({})["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "LOCALHOST"


def test_a_node_applies_the_defaults_before_rclpy_init():
    code = (
        "import os, rclpy\n"
        "from ros_tutorials_common.ros import init\n"
        "init(['probe'])\n"
        "print(os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'], rclpy.ok())\n"
        "rclpy.shutdown()\n"
    )
    result = subprocess.run(
        [sys.executable, "-c", code],
        env=env_without_dds_defaults(),
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )
    assert result.stdout.split() == ["LOCALHOST", "True"], result.stderr


def test_launched_processes_get_the_defaults(tmp_path):
    launch = tmp_path / "env.launch.xml"
    launch.write_text(
        "<launch>\n"
        "  <executable cmd=\"sh -c 'echo range=$ROS_AUTOMATIC_DISCOVERY_RANGE'\""
        ' name="show_env" output="screen"/>\n'
        "</launch>\n"
    )
    result = subprocess.run(
        [sys.executable, "-m", "launcher", str(launch)],
        env=env_without_dds_defaults(),
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )
    assert "range=LOCALHOST" in result.stdout, result.stdout + result.stderr
    assert result.returncode == 0
