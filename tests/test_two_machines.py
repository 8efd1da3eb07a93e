"""Beyond one machine: two network namespaces joined by a virtual cable (a veth pair).

Each namespace stands for a machine with its own network stack: its own loopback and one
interface with an address in a private range (10.253.15.0/24), which exists only inside the
two namespaces, so no packet of these tests reaches a real network. Needs root and the `ip`
tool; skipped otherwise, with the reason.

- With the project's default (ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST) a publisher on one
  "machine" and a subscriber on the other never see each other.
- With ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET and one ROS_DOMAIN_ID, as the README tells users,
  the topic lesson, a service call and union.launch split across the two work.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from helpers import NodeProcess
from test_launcher_run import stamps

SUBNET = {"ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET"}
ADDRESSES = ("10.253.15.1/24", "10.253.15.2/24")


def _why_not() -> str | None:
    if sys.platform != "linux":
        return "network namespaces are Linux only"
    if os.geteuid() != 0:
        return "creating network namespaces needs root"
    if shutil.which("ip") is None:
        return "the `ip` tool (iproute2) is not installed"
    return None


pytestmark = pytest.mark.skipif(_why_not() is not None, reason=_why_not() or "")


def _ip(*args: str) -> None:
    done = subprocess.run(["ip", *args], capture_output=True, text=True, timeout=30)
    if done.returncode != 0:
        raise RuntimeError(f"ip {' '.join(args)}: {done.stderr.strip()}")


@pytest.fixture(scope="module")
def machines() -> Iterator[tuple[str, str]]:
    """Two network namespaces joined by a veth pair; both removed at the end, even on failure."""
    tag = f"{os.getpid() % 100000}"
    names = (f"rt{tag}a", f"rt{tag}b")
    links = (f"rtv{tag}a", f"rtv{tag}b")
    try:
        for name in names:
            _ip("netns", "add", name)
    except RuntimeError as error:
        for name in names:
            subprocess.run(["ip", "netns", "del", name], capture_output=True, timeout=30)
        pytest.skip(f"cannot create network namespaces here: {error}")
    try:
        # Created inside the first namespace with its peer in the second: the cable never
        # exists in this machine's own network namespace.
        _ip("-n", names[0], "link", "add", links[0], "type", "veth", "peer", "name", links[1],
            "netns", names[1])  # fmt: skip
        for name, link, address in zip(names, links, ADDRESSES, strict=True):
            _ip("-n", name, "addr", "add", address, "dev", link)
            _ip("-n", name, "link", "set", "lo", "up")  # Fast DDS needs loopback too
            _ip("-n", name, "link", "set", link, "up")
            # DDS discovery is multicast; with no default route it needs a route for it.
            _ip("-n", name, "route", "add", "224.0.0.0/4", "dev", link)
        yield names
    finally:
        for name in names:
            subprocess.run(["ip", "netns", "del", name], capture_output=True, timeout=30)


class MachineProcess(NodeProcess):
    """A Python program run inside a network namespace (`ip netns exec NS python ...`)."""

    def __init__(self, namespace: str, *args: str, env: dict[str, str] | None = None) -> None:
        super().__init__(*args, env=env, prefix=("ip", "netns", "exec", namespace))


@pytest.fixture
def on_machine(ros_domain: int) -> Iterator:
    started: list[MachineProcess] = []

    def start(namespace: str, *args: str, env: dict[str, str] | None = None) -> MachineProcess:
        proc = MachineProcess(namespace, *args, env=env)
        started.append(proc)
        return proc

    yield start
    for proc in started:
        proc.kill()


def received(lines: list[str]) -> int:
    return sum(" recieve msg = " in line for line in lines) // 3


def test_default_localhost_range_keeps_the_machines_apart(machines, on_machine):
    a, b = machines
    publisher = on_machine(a, "-m", "ros_tutorials_topic.publisher")
    same_machine = on_machine(a, "-m", "ros_tutorials_topic.subscriber")
    other_machine = on_machine(b, "-m", "ros_tutorials_topic.subscriber")
    # The subscriber beside the publisher hears 20 messages (2 s at 10 Hz): discovery had
    # every chance; the one on the other machine, started at the same time, heard nothing.
    same_machine.wait_for_output(lambda lines: received(lines) >= 20, what="20 messages on A")
    assert received(other_machine.lines) == 0, other_machine.output
    assert other_machine.process.poll() is None and publisher.process.poll() is None


def test_subnet_range_topic_lesson_across_machines(machines, on_machine):
    a, b = machines
    publisher = on_machine(a, "-m", "ros_tutorials_topic.publisher", env=SUBNET)
    subscriber = on_machine(b, "-m", "ros_tutorials_topic.subscriber", env=SUBNET)
    lines = subscriber.wait_for_output(lambda lines: received(lines) >= 3, what="3 messages on B")
    # What B received is what A sent: the same stamps (A's own lines may lag a little).
    got = {line.rsplit("= ", 1)[1] for line in lines if "recieve msg" in line}

    def sent(lines: list[str]) -> set[str]:
        return {line.rsplit("= ", 1)[1] for line in lines if "send msg" in line}

    publisher.wait_for_output(lambda lines: got <= sent(lines), what="A having sent what B got")
    assert subscriber.interrupt() == 0 and publisher.interrupt() == 0


def test_subnet_range_service_call_across_machines(machines, on_machine):
    a, b = machines
    server = on_machine(a, "-m", "ros_tutorials_service.server", env=SUBNET)
    server.wait_for_output(lambda lines: any("ready srv server!" in x for x in lines))
    client = on_machine(b, "-m", "ros_tutorials_service.client", "2", "3", "--timeout", "20",
                        env=SUBNET)  # fmt: skip
    assert client.wait() == 0, client.output
    assert "receive srv, srv.Response.result: 5" in client.output
    server.wait_for_output(lambda lines: any("request: x=2, y=3" in x for x in lines))
    assert server.interrupt() == 0, server.output


def _split_union_launch(folder: Path) -> tuple[Path, Path]:
    """union.launch in two halves: the publishers for machine A, the subscribers for B."""
    halves = []
    for kind in ("publisher", "subscriber"):
        groups = "".join(
            f'<group ns="{ns}"><node pkg="ros_tutorials_topic" type="topic_{kind}" '
            f'name="topic_{kind}"/></group>'
            for ns in ("ns1", "ns2")
        )
        path = folder / f"union_{kind}s.launch"
        path.write_text(f"<launch>{groups}</launch>\n")
        halves.append(path)
    return halves[0], halves[1]


def test_subnet_range_union_launch_split_across_machines(machines, on_machine, tmp_path):
    a, b = machines
    publishers, subscribers = _split_union_launch(tmp_path)
    launch_a = on_machine(a, "-m", "launcher", str(publishers), "--screen", env=SUBNET)
    launch_b = on_machine(b, "-m", "launcher", str(subscribers), "--screen", env=SUBNET)

    def both_groups_heard(lines: list[str]) -> bool:
        return all(
            len(stamps(lines, f"{ns}/topic_subscriber", "recieve")) >= 3 for ns in ("ns1", "ns2")
        )

    lines = launch_b.wait_for_output(both_groups_heard, what="both groups heard on B")
    heard = {ns: stamps(lines, f"{ns}/topic_subscriber", "recieve") for ns in ("ns1", "ns2")}
    # Each subscriber on B heard its own group's publisher on A (A's lines may lag a little).
    sent = launch_a.wait_for_output(
        lambda sent: all(
            heard[ns] <= stamps(sent, f"{ns}/topic_publisher", "send") for ns in heard
        ),
        what="A's publishers having sent what B heard",
    )
    for ns, other in (("ns1", "ns2"), ("ns2", "ns1")):
        assert not heard[ns] & stamps(sent, f"{other}/topic_publisher", "send")
    assert launch_b.interrupt() == 130 and launch_a.interrupt() == 130
