"""`ros2 doctor` (also `ros2 wtf`): checks of this environment and of the running system.

As ros2doctor (ROS 2 Jazzy) and the tutorial "Using ros2doctor to identify issues" print it:
each check prints what it finds as `<file>: <line>: UserWarning: <message>` on stderr (an
error: `UserWarning: ERROR: <message>`, and the check fails), then `All <n> checks passed` or
`<n>/<m> check(s) failed` and `Failed modules: ...`; `--report` prints the sections
(`   NETWORK CONFIGURATION`, ... `   TOPIC LIST`) as `key  : value` lines.

What ros2doctor learns from rosdistro on the internet (the distribution's status, its
package versions) comes here from this environment: the pinned ROS 2 Jazzy wheels. Checks
ros2doctor does not have, for a learner on PyPI's ROS 2 and for a classroom: the Python and
the virtual environment, the project's packages in this environment's ament index, the DDS
settings (ROS_DOMAIN_ID, ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_STATIC_PEERS, ROS_LOCALHOST_ONLY),
nodes of one name (ros2doctor's Rolling NodeCheck), who else is in this ROS_DOMAIN_ID and a
free one to use instead, and (only with the SUBNET range) whether multicast works.
"""

from __future__ import annotations

import argparse
import importlib.metadata
import os
import platform
import pwd
import random
import re
import sys
import sysconfig
import time
import xml.etree.ElementTree as ElementTree
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

from ros2cmd import netcheck
from ros2cmd.discovery import participant_of
from ros2cmd.graph import Graph, is_hidden
from ros2cmd.local_participants import EPROSIMA, domain_processes, heard_from_all, process_of
from ros2cmd.wait import spin_until
from ros_tutorials_common.dds import DDS_DEFAULTS, PRIVATE_DOMAIN_IDS, peer_name_ok

DISTRIBUTION = "jazzy"  # the ROS 2 of the pinned wheels (ros-jazzy-*)
PROJECT = "ros-tutorials"
MAX_DOMAIN_ID = 232  # Fast DDS: 7400 + 250 * id must leave room for the ports below 65536
PORTABLE_DOMAIN_IDS = 101  # above, ports may meet the OS's ephemeral ports (ROS 2 docs)
RANGES = ("LOCALHOST", "SUBNET", "OFF", "SYSTEM_DEFAULT")
SKIP_TOPICS = ("/parameter_events", "/rosout")  # ros2doctor's topic check leaves them out
# The checks that look at the running system (skipped when no node can be started).
GRAPH_CHECKS = ("node_check", "participant_check", "qos_compatibility_check", "topic_check")
FREE_DOMAIN_TRIES = 3  # domains listened to at once for a free one (SUBNET)

HELP = """\
Checks this environment and the running system, and says what may stop ROS 2 from working:
the Python and virtual environment of the ROS 2 Jazzy wheels, this project's packages in the
ament index, the DDS settings (ROS_DOMAIN_ID, ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_STATIC_PEERS,
ROS_LOCALHOST_ONLY), the network interfaces,
and in the running system: nodes that share a name, topics with a publisher and no
subscriber or the reverse, incompatible QoS, and the DDS participants of other users or
machines in this ROS_DOMAIN_ID (then it suggests a free domain id, one where nothing is heard:
on this machine from its open ports, at once; on the network by listening 3 s).
It sends nothing beyond this machine unless ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET: only then
does it send one datagram to DDS's multicast group 239.255.0.1 (port 7399) to see it come
back, and listen to the DDS announcements on the network. It takes a few seconds."""


# ros2doctor's output: warnings as Python prints them, reports as key: value lines.


def _emit(message: str, depth: int) -> None:
    frame = sys._getframe(depth + 1)
    print(f"{frame.f_code.co_filename}: {frame.f_lineno}: UserWarning: {message}", file=sys.stderr)


def doctor_warn(message: str) -> None:
    """`<file>: <line>: UserWarning: <message>`, the file and line of the caller."""
    _emit(message, 1)


def doctor_error(message: str) -> None:
    _emit(f"ERROR: {message}", 1)


@dataclass
class Result:
    error: int = 0
    warning: int = 0


@dataclass
class Report:
    name: str
    items: list[tuple[str, object]] = field(default_factory=list)

    def add(self, key: str, value: object) -> None:
        self.items.append((key, value))


def format_print(report: Report) -> None:
    """As ros2doctor: the name after a blank line, keys padded to the longest plus 4."""
    print("\n  ", report.name)
    if not report.items:
        return
    longest = max(len(key) for key, _ in report.items)
    padding = longest + 4 if longest >= 8 else 8
    for key, value in report.items:
        print(f"{key:{padding}}: {value}")


# What the user set (read before rclpy.init, which applies this project's defaults).


@dataclass
class Settings:
    domain_text: str | None
    range_text: str | None
    static_peers: str | None
    localhost_only: str | None
    ros_distro: str | None

    @classmethod
    def from_environment(cls) -> Settings:
        env = os.environ
        return cls(
            env.get("ROS_DOMAIN_ID"),
            env.get("ROS_AUTOMATIC_DISCOVERY_RANGE"),
            env.get("ROS_STATIC_PEERS"),
            env.get("ROS_LOCALHOST_ONLY"),
            env.get("ROS_DISTRO"),
        )

    @property
    def domain_id(self) -> int | None:
        """The domain id, or None if it is not one Fast DDS can use."""
        text = (self.domain_text or "0").strip()
        if not text.isdigit() or int(text) > MAX_DOMAIN_ID:
            return None
        return int(text)

    def domain_problem(self) -> str | None:
        if self.domain_id is not None:
            return None
        text = self.domain_text
        if text.strip().isdigit():
            what = f"is above {MAX_DOMAIN_ID}, the largest domain id Fast DDS can use"
        else:
            what = "is not a whole number"
        return f"ROS_DOMAIN_ID={text!r} {what}: use one from 0 to {PORTABLE_DOMAIN_IDS}"

    @property
    def discovery_range(self) -> str:
        """The range every process here uses: the user's, else this project's default."""
        if self.localhost_only == "1":
            return "LOCALHOST"  # rcl honours the deprecated variable over the range
        if self.range_text is None:
            return DDS_DEFAULTS["ROS_AUTOMATIC_DISCOVERY_RANGE"]
        if not self.range_text:
            return "SUBNET"  # set but empty: rcl's own default
        return self.range_text if self.range_text in RANGES else "LOCALHOST"  # as rcl does

    def describe_range(self) -> str:
        text = self.discovery_range
        if self.localhost_only == "1":
            return f"{text} (ROS_LOCALHOST_ONLY=1)"
        if self.range_text is None:
            return f"{text} (this project's default)"
        if self.range_text and self.range_text not in RANGES:
            return f"{text} (rcl's reading of {self.range_text!r})"
        return text

    @property
    def subnet(self) -> bool:
        return self.discovery_range in ("SUBNET", "SYSTEM_DEFAULT")


# The running system: one look, shared by the checks and the reports.


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

    # The checks, in ros2doctor's order (its entry points' names, sorted).

    def domain_check(self) -> Result:
        result = Result()
        settings = self.settings
        problem = settings.domain_problem()
        if problem:
            doctor_error(f"{problem}; the running system was not checked")
            result.error += 1
        if settings.range_text and settings.range_text not in RANGES:
            doctor_warn(
                f"ROS_AUTOMATIC_DISCOVERY_RANGE={settings.range_text} is not one of "
                f"{', '.join(RANGES)}: rcl takes it as LOCALHOST"
            )
            result.warning += 1
        if settings.localhost_only is not None:
            doctor_warn(
                f"ROS_LOCALHOST_ONLY={settings.localhost_only} is deprecated: use "
                "ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST (or SUBNET) and ROS_STATIC_PEERS"
            )
            result.warning += 1
        peers = [p.strip() for p in (settings.static_peers or "").split(";") if p.strip()]
        for peer in peers:
            if not peer_name_ok(peer):
                doctor_warn(f"ROS_STATIC_PEERS: {peer!r} is not an IP address or a host name")
                result.warning += 1
        if settings.discovery_range == "OFF" and not peers:
            doctor_warn(
                "ROS_AUTOMATIC_DISCOVERY_RANGE=OFF and no ROS_STATIC_PEERS: "
                "no other process can be discovered"
            )
            result.warning += 1
        return result

    def multicast_check(self) -> Result:
        result = Result()
        ok, detail = self.multicast
        if not ok:
            doctor_error(
                f"multicast did not come back to this machine ({detail}): with "
                "ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET, DDS finds other machines by multicast; "
                "without it list them in ROS_STATIC_PEERS"
            )
            result.error += 1
        return result

    def network_check(self) -> Result:
        """ros2doctor's NetworkCheck: a loopback, a non-loopback and a multicast interface."""
        result = Result()
        found = [i for i in self.interfaces if i.flags >= 0]
        if not any(i.loopback for i in found):
            doctor_error("No loopback IP address is found.")
            result.error += 1
        if not any(not i.loopback for i in found):
            doctor_warn("Only loopback IP address is found.")
            result.warning += 1
        if not any(i.multicast for i in found):
            doctor_warn("No multicast IP address is found.")
            result.warning += 1
        return result

    def node_check(self) -> Result:
        result = Result()
        for name, count in sorted(Counter(self.system.nodes).items()):
            if count > 1:
                doctor_warn(f"Duplicate node name: {name}")
                result.warning += 1
        return result

    def package_check(self) -> Result:
        result = Result()
        missing = [name for name in project_packages() if name not in local_packages()]
        if missing:
            doctor_error(
                f"packages of this project missing from the ament index of {sys.prefix}: "
                f"{' '.join(missing)}; run `make setup`"
            )
            result.error += 1
        for requirement, pinned, installed in pinned_wheels():
            if installed != pinned:
                doctor_warn(
                    f"{requirement} is {installed or 'not installed'} here, this project pins "
                    f"{pinned}: run `make setup`"
                )
                result.warning += 1
        return result

    def participant_check(self) -> Result:
        result = Result()
        others = self.others()
        if not others:
            return result
        self.fill_addresses()
        free = self.free_domain
        advice = (
            f"ROS_DOMAIN_ID {free} has none: `export ROS_DOMAIN_ID={free}` in each of your "
            "terminals to work apart"
            if free is not None
            else "no free domain id was found to suggest"
        )
        doctor_warn(
            f"{len(others)} other participant(s) in ROS_DOMAIN_ID {self.domain_id} "
            f"that are not your processes here: "
            f"{'; '.join(p.describe() for p in others)}. {advice}"
        )
        result.warning += 1
        return result

    def platform_check(self) -> Result:
        result = Result()
        distro = self.settings.ros_distro
        if distro and distro.lower() != DISTRIBUTION:
            doctor_warn(
                f"ROS_DISTRO is {distro}, but this environment's ROS 2 is {DISTRIBUTION} "
                "(the wheels): a ROS installation sourced in this terminal may mix in"
            )
            result.warning += 1
        supported = python_range()
        version = platform.python_version()
        if supported and not _python_in(supported):
            doctor_error(f"Python {version} is outside the wheels' range ({supported})")
            result.error += 1
        if sys.prefix == sys.base_prefix:
            doctor_error(
                "not in a virtual environment: the ROS 2 wheels find their libraries only "
                "inside one (make setup creates .venv)"
            )
            result.error += 1
        return result

    def qos_compatibility_check(self) -> Result:
        from rclpy.qos import QoSCompatibility, qos_check_compatible

        result = Result()
        for topic, (_types, publishers, subscribers) in sorted(self.system.topics.items()):
            for pub in publishers:
                for sub in subscribers:
                    compatibility, reason = qos_check_compatible(pub.qos_profile, sub.qos_profile)
                    reason = re.sub(r"^(?i:warning|error): ", "", reason)
                    if compatibility == QoSCompatibility.WARNING:
                        doctor_warn(f"QoS compatibility warning found on topic '{topic}': {reason}")
                        result.warning += 1
                    elif compatibility == QoSCompatibility.ERROR:
                        doctor_error(f"QoS compatibility error found on topic '{topic}': {reason}")
                        result.error += 1
        return result

    def topic_check(self) -> Result:
        result = Result()
        for topic, (_types, publishers, subscribers) in sorted(self.system.topics.items()):
            if topic in SKIP_TOPICS:
                continue
            if publishers and not subscribers:
                doctor_warn(f"Publisher without subscriber detected on {topic}.")
                result.warning += 1
            elif subscribers and not publishers:
                doctor_warn(f"Subscriber without publisher detected on {topic}.")
                result.warning += 1
        return result

    def checks(self, exclude_packages: bool) -> list[tuple[str, Callable[[], Result]]]:
        """(category, check) in ros2doctor's order; those that cannot run here left out."""
        checks = [
            ("domain", self.domain_check),
            ("network", self.multicast_check if self.settings.subnet else None),
            ("network", self.network_check),
            ("node", self.node_check),
            ("package", None if exclude_packages else self.package_check),
            ("domain", self.participant_check),
            ("platform", self.platform_check),
            ("middleware", self.qos_compatibility_check),
            ("topic", self.topic_check),
        ]
        return [(category, check) for category, check in checks if check is not None]

    def run_checks(self, include_warnings: bool, exclude_packages: bool) -> tuple[list, int, int]:
        failed: list[str] = []
        fail = total = 0
        # The graph first: every check then reads the same complete look at it.
        system = self.system
        for category, check in self.checks(exclude_packages):
            if system is None and check.__name__ in GRAPH_CHECKS:
                continue  # nothing to look at; the check that stopped it has said why
            result = check()
            if result.error or (include_warnings and result.warning):
                fail += 1
                if category not in failed:
                    failed.append(category)
            total += 1
        if self.blocked and not self.settings.domain_problem():
            doctor_error(f"{self.blocked}; the running system was not checked")
            fail += 1
            failed.append("domain")
        return failed, fail, total

    # The reports, in ros2doctor's order (its entry points' names, sorted).

    def reports(self, categories: list[str] | None, exclude_packages: bool) -> list[Report]:
        makers = [
            ("network", self.network_report),
            ("node", self.node_report),
            ("package", None if exclude_packages else self.package_report),
            ("domain", self.participant_report),
            ("platform", self.platform_report),
            ("middleware", self.qos_compatibility_report),
            ("middleware", self.rmw_report),
            ("platform", self.rosdistro_report),
            ("topic", self.topic_report),
        ]
        return [
            make()
            for category, make in makers
            if make is not None and (categories is None or category in categories)
        ]

    def network_report(self) -> Report:
        report = Report("NETWORK CONFIGURATION")
        for interface in self.interfaces:
            for key, value in interface.report_items():
                report.add(key, value)
        if self.multicast is None:
            report.add(
                "multicast",
                f"not tried: ROS_AUTOMATIC_DISCOVERY_RANGE={self.settings.discovery_range} "
                "keeps DDS traffic on this machine",
            )
        else:
            ok, detail = self.multicast
            group = f"{netcheck.DDS_MULTICAST_GROUP}:{netcheck.MULTICAST_TEST_PORT}"
            report.add("multicast", f"{group} came back in {detail}" if ok else detail)
        return report

    def _not_looked_at(self, report: Report) -> Report | None:
        if self.system is None:
            report.add("status", f"not looked at: {self.blocked}")
            return report
        return None

    def node_report(self) -> Report:
        report = Report("NODE LIST")
        if self._not_looked_at(report):
            return report
        nodes = self.system.nodes
        report.add("node count", len(nodes))
        for name in nodes or ["none"]:
            report.add("node", name)
        return report

    def package_report(self) -> Report:
        """ros2doctor's `latest=` is rosdistro's release; here the pinned wheel's version."""
        report = Report("PACKAGE VERSIONS")
        wheels = wheel_versions()
        for name, local in local_packages().items():
            latest = wheels.get(f"ros-{DISTRIBUTION}-{name.replace('_', '-')}", "N/A")
            report.add(name, f"latest={latest}, local={local}")
        return report

    def participant_report(self) -> Report:
        report = Report("DOMAIN PARTICIPANTS")
        settings = self.settings
        report.add("domain id", self._domain_id_text())
        report.add("discovery range", settings.describe_range())
        report.add("static peers", settings.static_peers or "none")
        if settings.localhost_only is not None:
            report.add("ROS_LOCALHOST_ONLY", f"{settings.localhost_only} (deprecated)")
        if self._not_looked_at(report):
            return report
        self.fill_addresses()
        for participant in self.system.participants or []:
            report.add("participant", participant.describe())
        if not self.system.participants:
            report.add("participant", "none but this one")
        free = self.free_domain
        report.add("free domain id", free if free is not None else "none found")
        return report

    def _domain_id_text(self) -> str:
        if self.domain_id is None:
            return "invalid"
        if self.domain_id > PORTABLE_DOMAIN_IDS:  # allowed, so not a check's warning
            return (
                f"{self.domain_id} (above {PORTABLE_DOMAIN_IDS}: its ports may meet the ports "
                f"the operating system hands out; 0 to {PORTABLE_DOMAIN_IDS} are safe)"
            )
        return str(self.domain_id)

    def platform_report(self) -> Report:
        report = Report("PLATFORM INFORMATION")
        report.add("system", platform.system())
        report.add("platform info", platform.platform())
        report.add("release", platform.release())
        report.add("processor", platform.processor())
        report.add("python", f"{platform.python_version()} ({sys.executable})")
        venv = sys.prefix if sys.prefix != sys.base_prefix else "none"
        report.add("virtual environment", venv)
        return report

    def qos_compatibility_report(self) -> Report:
        from rclpy.qos import QoSCompatibility, qos_check_compatible

        report = Report("QOS COMPATIBILITY LIST")
        if self._not_looked_at(report):
            return report
        for topic, (_types, publishers, subscribers) in sorted(self.system.topics.items()):
            for pub in publishers:
                for sub in subscribers:
                    compatibility, reason = qos_check_compatible(pub.qos_profile, sub.qos_profile)
                    report.add("topic [type]", f"{topic} [{pub.topic_type}]")
                    report.add("publisher node", pub.node_name)
                    report.add("subscriber node", sub.node_name)
                    status = "OK" if compatibility == QoSCompatibility.OK else reason
                    report.add("compatibility status", status)
        if not report.items:
            report.add("compatibility status", "No publisher/subscriber pairs found")
        return report

    def rmw_report(self) -> Report:
        from rclpy.utilities import get_rmw_implementation_identifier

        report = Report("RMW MIDDLEWARE")
        report.add("middleware name", get_rmw_implementation_identifier())
        return report

    def rosdistro_report(self) -> Report:
        """ros2doctor reads rosdistro; here the distribution of the installed wheels."""
        report = Report("ROS 2 INFORMATION")
        report.add("distribution name", DISTRIBUTION)
        report.add("distribution type", "ros2")
        report.add("distribution status", "active")
        report.add("release platforms", {"pypi": wheel_platforms()})
        return report

    def topic_report(self) -> Report:
        report = Report("TOPIC LIST")
        if self._not_looked_at(report):
            return report
        topics = {n: t for n, t in sorted(self.system.topics.items()) if n not in SKIP_TOPICS}
        if not topics:
            report.add("topic", "none")
            report.add("publisher count", 0)
            report.add("subscriber count", 0)
        for name, (_types, publishers, subscribers) in topics.items():
            report.add("topic", name)
            report.add("publisher count", len(publishers))
            report.add("subscriber count", len(subscribers))
        return report


# This environment: its packages and wheels.


def local_packages() -> dict[str, str]:
    """Every package in this environment's ament index and its package.xml version."""
    from ros_tutorials_common import ament

    found = {}
    for name, prefix in ament.packages().items():
        try:
            root = ElementTree.parse(prefix / "share" / name / "package.xml").getroot()
            found[name] = (root.findtext("version") or "").strip()
        except (OSError, ElementTree.ParseError):
            found[name] = ""
    return found


def project_packages() -> list[str]:
    """This project's packages: its Python packages with a package.xml, and its interfaces."""
    root = Path(__file__).resolve().parent.parent
    names = [
        manifest.parent.name
        for pattern in ("ros_tutorials_*/package.xml", "interfaces/*/package.xml")
        for manifest in root.glob(pattern)
    ]
    return sorted(names)


def wheel_versions() -> dict[str, str]:
    """Installed distributions: normalised name -> version."""
    return {
        re.sub(r"[-_.]+", "-", dist.metadata["Name"]).lower(): dist.version
        for dist in importlib.metadata.distributions()
        if dist.metadata["Name"]
    }


def pinned_wheels() -> list[tuple[str, str, str | None]]:
    """The ROS 2 wheels this project pins: (name, pinned version, installed version)."""
    try:
        requirements = importlib.metadata.requires(PROJECT) or []
    except importlib.metadata.PackageNotFoundError:
        return []
    installed = wheel_versions()
    pinned = []
    for requirement in requirements:
        match = re.match(r"(ros-[a-z]+-[a-z0-9-]+)(\[[^]]*\])?==([^;\s]+)(.*)", requirement)
        if match and "extra ==" not in match.group(4):
            name = match.group(1)
            pinned.append((name, match.group(3), installed.get(name)))
    return pinned


def python_range() -> str | None:
    try:
        return importlib.metadata.metadata(PROJECT)["Requires-Python"]
    except (importlib.metadata.PackageNotFoundError, KeyError):
        return None


def _python_in(specifier: str) -> bool:
    """Whether this Python satisfies `>=3.10,<3.14` (the simple forms pyproject uses)."""
    current = sys.version_info[:2]
    for part in specifier.split(","):
        match = re.fullmatch(r"\s*(>=|<=|<|>|==)\s*(\d+)\.(\d+)\s*", part)
        if not match:
            continue
        bound = (int(match.group(2)), int(match.group(3)))
        op = match.group(1)
        if not {
            ">=": current >= bound,
            "<=": current <= bound,
            "<": current < bound,
            ">": current > bound,
            "==": current == bound,
        }[op]:
            return False
    return True


def wheel_platforms() -> list[str]:
    """Where the wheels of this environment run: this platform, the Pythons they support."""
    return [f"{sysconfig.get_platform()}, Python {python_range() or '?'}"]


# The command.


def doctor(args: argparse.Namespace) -> None:
    settings = Settings.from_environment()
    run = Doctor(settings)
    try:
        if args.report:
            for report in run.reports(None, args.exclude_packages):
                format_print(report)
            return
        failed, fail, total = run.run_checks(args.include_warnings, args.exclude_packages)
        if fail:
            print(f"\n{fail}/{total} check(s) failed\n")
            print("Failed modules:", *failed)
        else:
            print(f"\nAll {total} checks passed\n")
        if args.report_failed and fail:
            for report in run.reports(failed, args.exclude_packages):
                format_print(report)
    finally:
        run.close()


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    """`ros2 doctor` and its alias `ros2 wtf`."""
    for name, summary in (
        ("doctor", "Check ROS setup and other potential issues"),
        ("wtf", "Use `wtf` as alias to `doctor`"),
    ):
        parser = verbs.add_parser(
            name,
            help=summary,
            description=HELP,
            formatter_class=argparse.RawDescriptionHelpFormatter,
        )
        group = parser.add_mutually_exclusive_group()
        group.add_argument("--report", "-r", action="store_true", help="Print all reports.")
        group.add_argument(
            "--report-failed",
            "-rf",
            action="store_true",
            help="Print reports of failed checks only.",
        )
        parser.add_argument(
            "--exclude-packages",
            "-ep",
            action="store_true",
            help="Exclude package checks or report.",
        )
        parser.add_argument(
            "--include-warnings",
            "-iw",
            action="store_true",
            help="Include warnings as failed checks. Warnings are ignored by default.",
        )
        parser.set_defaults(offline=True, run=lambda _graph, a: doctor(a))
