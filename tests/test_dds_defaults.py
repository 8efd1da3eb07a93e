"""The DDS defaults reach every process this project starts, and a user's choice wins."""

from __future__ import annotations

import contextlib
import os
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import BIN, TIMEOUT, NodeProcess

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


def udp_ports(pid: int) -> set[int]:
    """The local ports of the UDP sockets process PID has open."""
    inodes = set()
    for fd in Path(f"/proc/{pid}/fd").iterdir():
        with contextlib.suppress(OSError):
            link = os.readlink(fd)
            if link.startswith("socket:["):
                inodes.add(link[len("socket:[") : -1])
    ports = set()
    for line in Path("/proc/net/udp").read_text().splitlines()[1:]:
        fields = line.split()
        if fields[9] in inodes:
            ports.add(int(fields[1].split(":")[1], 16))
    return ports


UNSET = [arg for name in DDS_DEFAULTS for arg in ("-u", name)]  # env(1): a shell without them
ACTIVATE = BIN / "activate"
STARTS = {
    "console script, not activated": ([*UNSET], [str(BIN / "talker")]),
    "ros2 run": ([*UNSET], [str(BIN / "ros2"), "run", "ros_tutorials_topic", "talker"]),
    "rosrun": ([*UNSET], [str(BIN / "rosrun"), "ros_tutorials_topic", "talker"]),
    "python -m, activated": (
        [*UNSET, "bash", "-c", f". {ACTIVATE} && exec python -m ros_tutorials_topic.talker"],
        [],
    ),
}


@pytest.mark.parametrize("how", STARTS)
def test_every_way_a_lesson_starts_keeps_discovery_on_this_machine(how: str, ros_domain: int):
    """A lesson sets no DDS defaults; started any way this project has, it gets them: its
    participant does not listen on the domain's multicast discovery port, as with SUBNET."""
    before, after = STARTS[how]
    talker = NodeProcess(*after, prefix=["env", *before])
    try:
        talker.wait_for_text("hello world")
        assert 7400 + 250 * ros_domain not in udp_ports(talker.process.pid), talker.output
    finally:
        talker.kill()


def test_the_users_discovery_range_wins(ros_domain: int):
    """The control: the user's SUBNET stays, and the participant listens on the port."""
    talker = NodeProcess(
        str(BIN / "talker"),
        prefix=["env", *UNSET, "ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET"],
    )
    try:
        talker.wait_for_text("hello world")
        assert 7400 + 250 * ros_domain in udp_ports(talker.process.pid), talker.output
    finally:
        talker.kill()
