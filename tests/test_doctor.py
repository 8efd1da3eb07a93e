"""`ros2 doctor`: the tutorial "Using ros2doctor to identify issues", in this session's domain.

What ros2doctor prints (ROS 2 Jazzy): warnings as `<file>: <line>: UserWarning: <message>` on
stderr, then `All <n> checks passed` or `<n>/<m> check(s) failed` and `Failed modules: ...`;
`--report` prints its sections. The network warnings depend on the machine: the test works
out which are true here from /sys/class/net, not from the doctor's own code.
"""

from __future__ import annotations

import importlib.metadata
import os
import pwd
import re
import subprocess
from pathlib import Path

import pytest
import test_two_machines as two
from helpers import BIN, run
from test_two_machines import ADDRESSES, MachineProcess, machines  # noqa: F401 - a fixture

from ros2cmd.local_participants import domain_processes
from ros_tutorials_common.dds import claim_private_domain_id

CHECKS = 8  # the checks with the project's LOCALHOST range (the multicast one is not tried)
# A plain rclpy node in a process of its own: NAME, and optionally a topic it publishes.
PLAIN_NODE = """
import sys, rclpy
from rclpy.node import Node
from std_msgs.msg import String
rclpy.init()
node = Node(sys.argv[1])
if len(sys.argv) > 2:
    node.create_publisher(String, sys.argv[2], 10)
print("ready", flush=True)
try:
    rclpy.spin(node)
except BaseException:
    pass
"""
IFF_LOOPBACK, IFF_MULTICAST = 0x8, 0x1000


def network_warnings() -> list[str]:
    """What ros2doctor's network check says on this machine (from /sys, not from ros2 doctor)."""
    flags = [int(p.read_text(), 16) for p in Path("/sys/class/net").glob("*/flags")]
    warnings = []
    if not any(not f & IFF_LOOPBACK for f in flags):
        warnings.append("Only loopback IP address is found.")
    if not any(f & IFF_MULTICAST for f in flags):
        warnings.append("No multicast IP address is found.")
    return warnings


def warnings_of(stderr: str) -> list[str]:
    """The messages of the UserWarning lines; every line of stderr must be one."""
    lines = stderr.strip().splitlines()
    pattern = re.compile(r"^/\S+/ros2cmd/doctor/\S+\.py: \d+: UserWarning: (.*)$")
    for line in lines:
        assert pattern.match(line), f"not a UserWarning line: {line!r}\n{stderr}"
    return [pattern.match(line).group(1) for line in lines]


def doctor(*args: str, env: dict[str, str] | None = None) -> tuple[str, list[str]]:
    result = run("ros2", "doctor", *args, env=env)
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    return result.stdout, warnings_of(result.stderr)


def sections(report: str) -> dict[str, list[tuple[str, str]]]:
    """`   NAME` then `key   : value` lines -> {NAME: [(key, value), ...]}."""
    found: dict[str, list[tuple[str, str]]] = {}
    current = None
    for line in report.splitlines():
        if line.startswith("   ") and line.strip().isupper():
            current = found.setdefault(line.strip(), [])
        elif line.strip():
            key, value = line.split(": ", 1) if ": " in line else (line.rstrip(":"), "")
            current.append((key.rstrip(), value))
    return found


def plain_node(node_process, name: str, *topic: str):
    proc = node_process("-c", PLAIN_NODE, name, *topic)
    proc.wait_for_text("ready")
    return proc


def test_a_clean_domain_passes_every_check(own_domain):
    stdout, warnings = doctor()
    assert stdout == f"\nAll {CHECKS} checks passed\n\n"
    assert warnings == network_warnings()


def test_report_has_the_tutorials_sections(own_domain):
    stdout, warnings = doctor("--report")
    assert warnings == []
    report = sections(stdout)
    assert list(report) == [
        "NETWORK CONFIGURATION",
        "NODE LIST",
        "PACKAGE VERSIONS",
        "DOMAIN PARTICIPANTS",
        "PLATFORM INFORMATION",
        "QOS COMPATIBILITY LIST",
        "RMW MIDDLEWARE",
        "ROS 2 INFORMATION",
        "TOPIC LIST",
    ]
    # ros2doctor's layout: keys padded to the longest key plus four spaces.
    assert "\n   ROS 2 INFORMATION\ndistribution name      : jazzy\n" in stdout
    assert report["RMW MIDDLEWARE"] == [("middleware name", "rmw_fastrtps_cpp")]
    assert ("device", "lo") in report["NETWORK CONFIGURATION"]
    assert (
        "multicast",
        "not tried: ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST keeps DDS traffic on this machine",
    ) in report["NETWORK CONFIGURATION"]
    assert report["TOPIC LIST"] == [
        ("topic", "none"),
        ("publisher count", "0"),
        ("subscriber count", "0"),
    ]
    assert report["NODE LIST"] == [("node count", "0"), ("node", "none")]
    packages = dict(report["PACKAGE VERSIONS"])
    assert packages["ros_tutorials_topic"] == "latest=N/A, local=0.1.0"
    wheel = importlib.metadata.version("ros-jazzy-rclpy")
    assert re.fullmatch(rf"latest={wheel}, local=\d+\.\d+\.\d+", packages["rclpy"])
    participants = dict(report["DOMAIN PARTICIPANTS"])
    assert participants["domain id"] == str(own_domain)
    assert participants["participant"] == "none but this one"


def test_another_process_in_the_domain_is_seen_and_a_free_domain_suggested(
    own_domain, node_process
):
    talker = plain_node(node_process, "lone_talker", "doctor_chatter")
    stdout, warnings = doctor("--report")
    participants = sections(stdout)["DOMAIN PARTICIPANTS"]
    user = pwd.getpwuid(os.getuid()).pw_name
    seen = [value for key, value in participants if key == "participant"]
    assert len(seen) == 1, stdout
    assert re.fullmatch(
        rf"pid {talker.process.pid} \(python\S* -c .*\) of user {user} on this machine: "
        r"/lone_talker",
        seen[0],
    ), seen
    free = int(dict(participants)["free domain id"])
    assert free != own_domain and 1 <= free <= 101
    assert domain_processes(free) == (False, {})  # nobody on this machine uses it
    # The learner's own process is no warning; its topic without a subscriber is.
    stdout, warnings = doctor()
    assert warnings == [
        *network_warnings(),
        "Publisher without subscriber detected on /doctor_chatter.",
    ]
    assert stdout == f"\nAll {CHECKS} checks passed\n\n"


def test_nodes_of_one_name_are_a_warning(own_domain, node_process):
    plain_node(node_process, "twin")
    plain_node(node_process, "twin")
    stdout, warnings = doctor("--include-warnings")
    assert warnings == [*network_warnings(), "Duplicate node name: /twin"]
    failed = 1 + bool(network_warnings())
    modules = "network node" if network_warnings() else "node"
    assert stdout == f"\n{failed}/{CHECKS} check(s) failed\n\nFailed modules: {modules}\n"


def test_hidden_topics_are_not_checked_or_reported(own_domain, node_process):
    """ros2doctor reads ros2topic's topic names without the hidden ones (a part starting with
    `_`, as turtlesim's canvas image and every action's topics)."""
    plain_node(node_process, "canvas_owner", "/turtlesim/_canvas/compressed")
    stdout, warnings = doctor()
    assert warnings == network_warnings()
    assert stdout == f"\nAll {CHECKS} checks passed\n\n"
    report = sections(doctor("--report")[0])
    assert report["TOPIC LIST"][0] == ("topic", "none")
    assert dict(report["NODE LIST"])["node"] == "/canvas_owner"


def test_a_domain_id_above_101_is_said_in_the_report_not_warned():
    """ros2doctor does not check ROS_DOMAIN_ID; 102 to 232 work, so the report says what
    to know about them and the checks stay quiet. (An id above 101 of this test's own, where
    no process runs: another run's would be seen by the checks.)"""
    for _ in range(10):
        domain_id, lock = claim_private_domain_id(range(102, 233))
        if not (domain_processes(domain_id) or (False,))[0]:
            break
        lock.close()
    with lock:
        env = {**os.environ, "ROS_DOMAIN_ID": str(domain_id)}
        stdout, warnings = doctor(env=env)
        assert not [w for w in warnings if "ROS_DOMAIN_ID" in w], warnings
        assert stdout == f"\nAll {CHECKS} checks passed\n\n"
        report = sections(doctor("--report", env=env)[0])
    assert dict(report["DOMAIN PARTICIPANTS"])["domain id"] == (
        f"{domain_id} (above 101: its ports may meet the ports the operating system hands "
        "out; 0 to 101 are safe)"
    )


@pytest.mark.parametrize(
    ("value", "problem"),
    [
        ("abc", "ROS_DOMAIN_ID='abc' is not a whole number in ASCII digits"),
        ("\uff11", "ROS_DOMAIN_ID='\uff11' is not a whole number in ASCII digits"),
        ("300", "ROS_DOMAIN_ID='300' is above 232, the largest domain id Fast DDS can use"),
    ],
)
def test_a_bad_domain_id_is_one_clear_line(value, problem):
    stdout, warnings = doctor(env={**os.environ, "ROS_DOMAIN_ID": value})
    assert warnings == [
        f"ERROR: {problem}: use one from 0 to 101; the running system was not checked",
        *network_warnings(),
    ]
    assert stdout == "\n1/4 check(s) failed\n\nFailed modules: domain\n"


@two.pytestmark  # root and `ip` for the network namespaces
def test_subnet_range_sees_another_machine_and_tests_multicast(machines):  # noqa: F811
    """Two network namespaces stand for two machines of a classroom (test_two_machines.py):
    with the SUBNET range the doctor on one sees the other's participant, with its address,
    suggests a free domain id, and its multicast datagram comes back."""
    a, b = machines
    env = {**os.environ, "ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET"}
    other = MachineProcess(b, "-c", PLAIN_NODE, "classmate", env=env)
    try:
        other.wait_for_text("ready")
        command = ["ip", "netns", "exec", a, str(BIN / "ros2"), "doctor"]
        result = subprocess.run(command, capture_output=True, text=True, env=env, timeout=60)
        assert result.returncode == 0 and "Traceback" not in result.stderr, result.stderr
        (warning,) = warnings_of(result.stderr)
        address = ADDRESSES[1].split("/")[0]
        match = re.fullmatch(
            rf"1 other participant\(s\) in ROS_DOMAIN_ID {os.environ['ROS_DOMAIN_ID']} that "
            rf"are not your processes here: a process on another machine \({address}\): "
            r"/classmate\. ROS_DOMAIN_ID (\d+) has none: `export ROS_DOMAIN_ID=\1` in each of "
            r"your terminals to work apart",
            warning,
        )
        assert match, warning
        assert result.stdout == f"\nAll {CHECKS + 1} checks passed\n\n"
    finally:
        other.kill()
