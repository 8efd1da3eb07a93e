"""A listing knows who runs on this machine (ros2cmd/local_participants.py).

The two facts it rests on, checked on the real Fast DDS: each participant holds a discovery
port of the domain's (found through /proc with its process), and its GUID prefix carries its
process id. Then: where those cannot be relied on, there is no answer (the listing waits the
announcement periods instead). That lists stay complete is tests/test_graph_complete.py's.
"""

from __future__ import annotations

import os
from collections import Counter
from pathlib import Path

import rclpy
from helpers import run, spin_until
from rclpy.context import Context
from rclpy.node import Node

from ros2cmd.local_participants import (
    heard_from_all,
    local_participants,
    process_of,
    unexplained,
)
from ros_tutorials_common import dds


def _prefix(pid: int, participant: int = 0) -> bytes:
    """A Fast DDS GUID prefix: vendor, host, process id (low 16 bits), random, participant."""
    vendor_and_host, random = b"\x01\x0f\x12\x34", b"\xab\xcd"
    return (
        vendor_and_host
        + (pid & 0xFFFF).to_bytes(2, "little")
        + random
        + participant.to_bytes(4, "little")
    )


def test_each_process_with_a_participant_is_counted_and_named_in_its_guid(
    context, executor, node_process, ros_domain
):
    talker = node_process("-m", "ros_tutorials_topic.talker")
    talker.wait_for_text("hello world")
    node = Node("_looking", context=context)
    executor.add_node(node)
    talker_pid, own_pid = talker.process.pid & 0xFFFF, os.getpid() & 0xFFFF

    counted = local_participants(ros_domain)

    assert counted is not None, "no answer, although discovery stays on this machine"
    assert counted[talker_pid] == 1, counted
    assert counted[own_pid] >= 1, counted  # this test's own node
    found: list[bytes] = []
    spin_until(
        executor,
        lambda: found.extend(node.get_publishers_info_by_topic("/chatter")) or found,
        what="the talker's publisher",
    )
    talker_prefix = bytes(found[0].endpoint_gid)[:12]
    assert process_of(talker_prefix) == talker_pid
    assert heard_from_all(Counter({talker_pid: 1}), {talker_prefix})
    assert not heard_from_all(Counter({talker_pid: 1}), {_prefix(talker_pid + 1)})

    # A second participant in this process (a context of its own) is one more port of ours.
    second = Context()
    rclpy.init(context=second)
    try:
        other = Node("_looking_too", context=second)
        try:
            again = local_participants(ros_domain)
            assert again is not None and again[own_pid] == counted[own_pid] + 1, again
        finally:
            other.destroy_node()
    finally:
        second.try_shutdown()


def test_no_answer_where_this_machine_cannot_know(context, executor, monkeypatch, ros_domain):
    executor.add_node(Node("_looking", context=context))
    assert local_participants(ros_domain) is not None
    # No participant of ours in that domain: the port layout is not confirmed.
    assert local_participants((ros_domain + 50) % 101 + 1) is None
    for name, value in (
        ("ROS_AUTOMATIC_DISCOVERY_RANGE", "SUBNET"),  # other machines may take part
        ("ROS_STATIC_PEERS", "192.168.0.2"),
        ("ROS_DISCOVERY_SERVER", "127.0.0.1:11811"),
    ):
        with monkeypatch.context() as patch:
            patch.setenv(name, value)
            assert local_participants(ros_domain) is None, f"{name}={value}"

    def unreadable(path: str) -> str:
        raise PermissionError(path)

    with monkeypatch.context() as patch:  # whose sockets these are cannot be seen
        patch.setattr(os, "readlink", unreadable)
        assert local_participants(ros_domain) is None


def test_heard_from_all_counts_participants_per_process():
    two_in_one = Counter({7: 2, 70000 & 0xFFFF: 1})
    assert not heard_from_all(two_in_one, {_prefix(7), _prefix(70000)})
    assert heard_from_all(two_in_one, {_prefix(7), _prefix(7, 1), _prefix(70000)})
    assert heard_from_all(Counter(), set())
    assert process_of(b"\x01\x10" + bytes(10)) is None  # another vendor's: no process id


def test_a_participant_the_count_cannot_explain_is_noticed():
    """A listing stops early only when every participant it saw is one of those counted."""
    mine = os.getpid() & 0xFFFF
    counted = Counter({mine: 1})
    assert not unexplained(counted, {_prefix(mine)})
    assert unexplained(counted, {_prefix(mine), _prefix(mine, 1)}), "more than it holds ports"
    assert unexplained(Counter(), {_prefix(mine)}), "a running process that holds no port"
    assert unexplained(counted, {b"\x01\x10" + bytes(10)}), "another vendor's"
    ended = next(
        low
        for low in range(300, 0xFFFF)
        if not any(os.path.exists(f"/proc/{pid}") for pid in range(low, 1 << 22, 0x10000))
    )
    assert not unexplained(counted, {_prefix(mine), _prefix(ended)}), "of a process now gone"


def test_a_listing_stops_once_it_has_heard_from_everyone(node_process, tmp_path):
    """With an announcement period so long that waiting it out five times would pass the
    listing's 10 s limit (and print a warning), `rosnode list` still ends without one: it
    stopped once it had heard from every participant on this machine."""
    profile = Path(dds.DDS_DEFAULTS["FASTRTPS_DEFAULT_PROFILES_FILE"]).read_text()
    slow = tmp_path / "slow_announcements.xml"
    slow.write_text(profile.replace("<sec>0</sec>", "<sec>15</sec>"))
    talker = node_process("-m", "ros_tutorials_topic.talker")
    talker.wait_for_text("hello world")
    env = {**os.environ, "FASTRTPS_DEFAULT_PROFILES_FILE": str(slow)}
    listed = run("rosnode", "list", env=env)
    assert listed.returncode == 0 and "/talker" in listed.stdout.split(), listed
    assert "warning" not in listed.stderr, listed.stderr
