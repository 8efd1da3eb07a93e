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


# A server and a client whose answers can never reach it: the client asks for TRANSIENT_LOCAL
# answers, which the server's VOLATILE response writer does not offer (their request ends
# match). The server gets the request, then its rmw waits for the client's reader for the
# response writer's max_blocking_time and drops the answer with a RuntimeWarning.
UNANSWERABLE = """
import sys, time, warnings
import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.qos import DurabilityPolicy, QoSProfile
from ros_tutorials_interfaces.srv import AddTwoInts

served = []
contexts = [Context(), Context()]
for context in contexts:
    rclpy.init(context=context)
server = rclpy.create_node("server", context=contexts[0])


def serve(request, response):
    served.append(time.monotonic())
    return response


server.create_service(AddTwoInts, "unanswerable", serve)
client = rclpy.create_node("client", context=contexts[1]).create_client(
    AddTwoInts, "unanswerable",
    qos_profile=QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL),
)
executor = SingleThreadedExecutor(context=contexts[0])
executor.add_node(server)
deadline = time.monotonic() + float(sys.argv[1])
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    while not served and time.monotonic() < deadline:
        client.call_async(AddTwoInts.Request(a=1, b=2))
        executor.spin_once(timeout_sec=0.5)  # returns once the answer is sent or dropped
if not served:
    sys.exit("the server never got a request")
print(f"{time.monotonic() - served[0]:.2f}")
print(*(str(warning.message) for warning in caught), sep="\\n")
"""


def blocked_answer(env: dict[str, str]) -> tuple[float, str]:
    """Seconds a server spent on an answer that could not be delivered, and its warnings."""
    result = subprocess.run(
        [sys.executable, "-c", UNANSWERABLE, str(TIMEOUT)],
        env=env,
        capture_output=True,
        text=True,
        timeout=2 * TIMEOUT,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    seconds, warnings = result.stdout.split("\n", 1)
    return float(seconds), warnings


def test_a_server_waits_5_s_for_a_client_it_has_not_found_yet(tmp_path):
    """The profile's "service" writer: a server that got a request before it found the
    client's reader waits up to 5 s for it, not Fast DDS's 100 ms, before dropping the answer
    (ros2/rmw_fastrtps#842). The control, the profile without that writer, drops it at once."""
    ours = DDS_DEFAULTS["FASTRTPS_DEFAULT_PROFILES_FILE"]
    seconds, warnings = blocked_answer({**os.environ, "FASTRTPS_DEFAULT_PROFILES_FILE": ours})
    assert "client will not receive response" in warnings
    assert seconds >= 4.5, f"the answer was dropped after {seconds} s"

    profile = Path(ours).read_text()
    without = tmp_path / "without_service_writer.xml"
    without.write_text(profile[: profile.index("  <data_writer")] + "</profiles>\n")
    env = {**os.environ, "FASTRTPS_DEFAULT_PROFILES_FILE": str(without)}
    seconds, warnings = blocked_answer(env)
    assert "client will not receive response" in warnings
    assert seconds < 4.5, f"without the profile's writer the answer waited {seconds} s"
