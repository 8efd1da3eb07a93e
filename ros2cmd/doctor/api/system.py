"""The running system as `ros2 doctor` sees it: one look (nodes, topics, the other DDS
participants and who they are), taken once and shared by the checks and the reports, and what
the network says (a free domain id, multicast, the interfaces)."""

from __future__ import annotations

import os
import pwd
import random
import time
from collections import Counter
from dataclasses import dataclass
from functools import cached_property

from ros2cmd import netcheck
from ros2cmd.discovery import participant_of
from ros2cmd.doctor.api import Report
from ros2cmd.doctor.api.settings import Settings
from ros2cmd.graph import Graph, is_hidden
from ros2cmd.local_participants import EPROSIMA, domain_processes, heard_from_all, process_of
from ros_tutorials_common.dds import PRIVATE_DOMAIN_IDS
from ros_tutorials_common.wait import spin_until

FREE_DOMAIN_TRIES = 3  # domains listened to at once for a free one (SUBNET)


@dataclass
class Participant:
    """A DDS participant (a ROS 2 process) in the domain, and what is known of it."""

    prefix: bytes
    nodes: list[str]
    this_machine: bool | None  # None: another vendor's, its host cannot be told
    pid: int | None = None
    user: str | None = None
    command: str | None = None
    address: str | None = None

    @property
    def yours(self) -> bool:
        return bool(self.this_machine) and self.user == _user_name(os.getuid())

    def describe(self) -> str:
        if self.this_machine:
            who = f"pid {self.pid} ({self.command})" if self.pid else "a process"
            owner = f" of user {self.user}" if self.user else ""
            where = f"{who}{owner} on this machine"
        elif self.this_machine is None:
            where = "a participant of another DDS implementation"
        else:
            where = "a process on another machine"
        if self.address and not self.this_machine:
            where += f" ({self.address})"
        nodes = ", ".join(self.nodes) if self.nodes else "no nodes"
        return f"{where}: {nodes}"


@dataclass
class System:
    nodes: list[str]  # full names, hidden ones too, ours left out
    topics: dict[str, tuple[list[str], list, list]]  # name -> (types, publishers, subscribers)
    participants: list[Participant]  # the others, ours left out


def _user_name(uid: int) -> str:
    try:
        return pwd.getpwuid(uid).pw_name
    except KeyError:
        return str(uid)


def _command_line(pid: int) -> str:
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as cmdline:
            words = cmdline.read().decode(errors="replace").split("\0")
    except OSError:
        return "?"
    words = [word for word in words if word]
    if not words:
        return "?"
    text = " ".join(" ".join([os.path.basename(words[0]), *words[1:]]).split())  # one line
    return text if len(text) <= 60 else text[:57] + "..."


class Doctor:
    """The checks and reports of one `ros2 doctor` run, with what they share."""

    def __init__(self, settings: Settings) -> None:
        self.settings = settings
        self.graph: Graph | None = None
        self.listener: netcheck.AnnouncementListener | None = None
        self.blocked = settings.domain_problem()
        self.domain_id = settings.domain_id

    def close(self) -> None:
        if self.listener is not None:
            self.listener.finish(wait=False)
        if self.graph is not None:
            self.graph.close()

    # The running system.

    @cached_property
    def system(self) -> System | None:
        """The graph once discovery is complete; None when no node can be started here."""
        if self.blocked:
            return None
        if self.settings.subnet:
            self.listener = netcheck.AnnouncementListener([self.domain_id, *self._candidates()])
        try:
            self.graph = Graph()
        except Exception as error:  # rcl refusing this environment: one line, not a traceback
            self.blocked = f"no ROS node could be started: {str(error).splitlines()[0]}"
            return None
        graph = self.graph
        graph.settle()
        if not spin_until(graph.executor, self._heard_everyone, 0):
            # settle() waits for this project's announcement period (0.25 s); a process
            # started with Fast DDS's default announces every 3 s.
            left = graph.started + netcheck.LISTEN_TIME - time.monotonic()
            spin_until(graph.executor, self._heard_everyone, max(left, 0), period=0.05)
            graph.settle()  # their nodes and endpoints too
        node = graph.node
        own = node.get_name()
        nodes = sorted(
            f"{ns.rstrip('/')}/{name}" for name, ns in node.get_node_names_and_namespaces()
        )
        if f"/{own}" in nodes:
            nodes.remove(f"/{own}")
        topics = {}
        for name, types in node.get_topic_names_and_types():
            if is_hidden(name):  # ros2doctor reads ros2topic's names without hidden ones
                continue
            publishers = [e for e in node.get_publishers_info_by_topic(name) if e.node_name != own]
            subscribers = [
                e for e in node.get_subscriptions_info_by_topic(name) if e.node_name != own
            ]
            topics[name] = (types, publishers, subscribers)
        return System(nodes, topics, self._participants())

    def _heard_everyone(self) -> bool:
        """Whether the graph has every participant this machine's open ports (and, with the
        SUBNET range, the announcements heard so far) say is in the domain."""
        seen = self.graph.participants()
        holders = domain_processes(self.domain_id)
        expected: Counter[int] = Counter()
        for pid, count in (holders[1] if holders else {}).items():
            expected[pid & 0xFFFF] += count
        return heard_from_all(expected, seen) and set(self._heard_here()) <= seen

    def _participants(self) -> list[Participant]:
        graph = self.graph
        own_name = graph.node.get_name()
        graph.discovery.take()
        latest = graph.discovery.latest
        own = [
            prefix
            for prefix, info in latest.items()
            if any(entry.node_name == own_name for entry in info.node_entities_info_seq)
        ]
        if not own:  # no ros_discovery_info: our node's own endpoints say which is ours
            own = [
                participant_of(bytes(e.endpoint_gid))
                for e in graph.node.get_publishers_info_by_topic("/parameter_events")
                if e.node_name == own_name
            ]
        own_prefix = own[0] if own else None
        holders = domain_processes(self.domain_id)
        pids = list(holders[1]) if holders else []
        found = []
        for prefix in sorted(graph.participants() - set(own)):
            info = latest.get(prefix)
            nodes = sorted(
                f"{entry.node_namespace.rstrip('/')}/{entry.node_name}"
                for entry in (info.node_entities_info_seq if info else [])
            )
            if prefix[:2] != EPROSIMA or own_prefix is None:
                this_machine = None
            else:
                this_machine = prefix[2:4] == own_prefix[2:4]  # Fast DDS's host id
            participant = Participant(prefix, nodes, this_machine)
            if this_machine:
                low = process_of(prefix)
                matches = [pid for pid in pids if pid & 0xFFFF == low] or [
                    int(entry)
                    for entry in os.listdir("/proc")
                    if entry.isdigit() and int(entry) & 0xFFFF == low
                ]
                if matches:
                    participant.pid = matches[0]
                    participant.command = _command_line(matches[0])
                    try:
                        participant.user = _user_name(os.stat(f"/proc/{matches[0]}").st_uid)
                    except OSError:
                        participant.user = None
            found.append(participant)
        return found

    def others(self) -> list[Participant]:
        """Participants that are not this user's processes on this machine."""
        system = self.system
        return [p for p in system.participants if not p.yours] if system else []

    def _candidates(self) -> list[int]:
        """Domain ids to suggest, tried in a random order (a classroom must not all move to one):
        those no process on this machine uses."""
        ids = [d for d in PRIVATE_DOMAIN_IDS if d != self.domain_id]
        random.shuffle(ids)
        free = []
        for domain_id in ids:
            holders = domain_processes(domain_id)
            if holders is not None and not holders[0]:
                free.append(domain_id)
                if not self.settings.subnet or len(free) == FREE_DOMAIN_TRIES:
                    break
        return free

    @cached_property
    def free_domain(self) -> int | None:
        """A domain id where no participant is heard: on this machine (its ports, at once)
        and, with the SUBNET range, on the network (listening LISTEN_TIME)."""
        if not self.settings.subnet:
            candidates = self._candidates()
            return candidates[0] if candidates else None
        if self.listener is None or self.listener.failed:
            return None
        self.listener.finish(wait=True)
        for domain_id, heard in self.listener.heard.items():
            if domain_id != self.domain_id and not heard:
                holders = domain_processes(domain_id)
                if holders is not None and not holders[0]:
                    return domain_id
        return None

    def fill_addresses(self) -> None:
        """The network addresses of other machines' participants, from their announcements."""
        if self.listener is None or self.system is None:
            return
        remote = [p for p in self.system.participants if not p.this_machine]
        if remote:
            self.listener.finish(wait=any(p.prefix not in self._heard_here() for p in remote))
        for participant in remote:
            participant.address = self._heard_here().get(participant.prefix)

    def _heard_here(self) -> dict[bytes, str]:
        return self.listener.heard.get(self.domain_id, {}) if self.listener else {}

    @cached_property
    def multicast(self) -> tuple[bool, str] | None:
        """Whether multicast comes back (None: not tried, traffic stays on this machine)."""
        if not self.settings.subnet:
            return None
        return netcheck.multicast_comes_back()

    @cached_property
    def interfaces(self) -> list[netcheck.Interface]:
        return netcheck.interfaces()

    def not_looked_at(self, report: Report) -> Report | None:
        if self.system is None:
            report.add("status", f"not looked at: {self.blocked}")
            return report
        return None
