"""Which processes on this machine hold a DDS participant in our domain, and how many each.

A listing must show everything that was running when it started, but discovery never says
"that was everyone": without more, the listing waits until every running participant has had
time to announce itself (graph.Graph.settle). On this machine the operating system can say who
is there. With ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST every participant that can be
discovered runs here, and Fast DDS gives each one a UDP port of its own for discovery, the RTPS
well-known "metatraffic unicast" port: 7400 + 250 * domain + 10 + 2 * i for the domain's i-th
participant on this machine (Fast DDS starts from the process's own participant number and
steps to the next free port). /proc/net/udp lists the bound ports with their sockets,
/proc/PID/fd says which process holds each socket, and a Fast DDS participant's GUID prefix
carries its process id (bytes 4 and 5: the id's low 16 bits). So a listing that has seen, for
every such process, as many participants as it holds ports, has heard from everyone that was
running when it looked. Counting per process, not per port, can only ask for more than is
there (a socket inherited by a forked child is counted for whichever holder is found first):
the listing then waits the announcement periods, never less. Participants that appear while
the listing waits are not in the first count; the listing counts again before it stops
(graph.Graph.settle), so a process's new participant cannot stand in for its old one.

Whenever that reasoning might not hold, ``local_participants`` answers None, or the listing
sees a participant the count does not explain (``unexplained``), and the listing waits the
announcement periods as before: another discovery range, static peers, a discovery
server, another RMW, no such port found for our own participant (another transport or port
layout), or a socket whose process we may not look at (another user's). What it cannot know: a
participant on this machine configured with no UDP transport at all (e.g.
FASTDDS_BUILTIN_TRANSPORTS=SHM in that process only); and only 16 bits of a process id are
in the GUID, so a participant still seen of a process that has just ended could be taken for
a running process whose id ends in the same 16 bits (about one chance in 65 536 each).
"""

from __future__ import annotations

import os
from collections import Counter

PORT_BASE, DOMAIN_GAIN, METATRAFFIC_UNICAST, PARTICIPANT_GAIN = 7400, 250, 10, 2  # RTPS 9.6.1.1
MAX_PARTICIPANTS = 120  # participant ports of one domain stay below the next domain's
EPROSIMA = b"\x01\x0f"  # the vendor id opening a Fast DDS GUID prefix


def process_of(prefix: bytes) -> int | None:
    """The low 16 bits of the process id in a Fast DDS participant's GUID prefix."""
    if prefix[:2] != EPROSIMA:
        return None
    return int.from_bytes(prefix[4:6], "little")


def local_participants(domain_id: int) -> Counter[int] | None:
    """Per process (low 16 bits of its id): how many participants it holds in the domain.

    None when this cannot be known (see the module's docstring); our own process is counted.
    """
    if not _only_this_machine():
        return None
    sockets = _discovery_sockets(domain_id)
    if sockets is None:
        return None
    owners = _owners(set(sockets))
    if owners is None or os.getpid() not in owners:
        return None
    expected: Counter[int] = Counter()
    for pid, count in owners.items():
        expected[pid & 0xFFFF] += count
    return expected


def domain_processes(domain_id: int) -> tuple[bool, Counter[int]] | None:
    """Whether any process on this machine holds a participant in the domain (whatever its
    discovery range), and per process id (the full id, of those we may look at) how many.

    None if the tables cannot be read. `ros2 doctor` asks it of its own domain and of the
    domains it may suggest instead.
    """
    sockets = _discovery_sockets(domain_id)
    if sockets is None:
        return None
    holders, _unowned = _holders(set(sockets))
    return bool(sockets), holders


def heard_from_all(expected: Counter[int], seen: set[bytes]) -> bool:
    """Whether the participants seen (GUID prefixes) include as many per process as expected."""
    found = Counter(process_of(prefix) for prefix in seen)
    return all(found[pid] >= count for pid, count in expected.items())


def still_there(expected: Counter[int], recount: Counter[int]) -> Counter[int]:
    """The processes of a first count that a later count still finds, each with no more
    participants than either count gives it: those that ended meanwhile need not be heard
    from, and those that started meanwhile were not running when the listing started."""
    return Counter(
        {pid: min(count, recount[pid]) for pid, count in expected.items() if recount[pid]}
    )


def unexplained(expected: Counter[int], seen: set[bytes]) -> bool:
    """Whether a participant seen is not one of those counted, so that the count cannot be
    trusted to hold everyone: another vendor's (no process id in its GUID), more of one
    process than it holds discovery ports, or one of a running process that holds none
    (a port layout of its own: another configuration, a participant number past
    MAX_PARTICIPANTS). A participant of a process that has ended meanwhile is no sign."""
    found = Counter(process_of(prefix) for prefix in seen)
    return any(
        pid is None or expected[pid] > 0 or _runs(pid)
        for pid, count in found.items()
        if pid is None or count > expected[pid]
    )


def _runs(low_bits: int) -> bool:
    """Whether a process runs whose id ends in these 16 bits."""
    try:
        with open("/proc/sys/kernel/pid_max") as pid_max:
            highest = int(pid_max.read())
    except (OSError, ValueError):
        return True  # cannot tell: assume it runs
    return any(os.path.exists(f"/proc/{pid}") for pid in range(low_bits, highest + 1, 0x10000))


def _only_this_machine() -> bool:
    import rclpy  # asked only with a graph node up, which has loaded it

    return (
        os.environ.get("ROS_AUTOMATIC_DISCOVERY_RANGE") == "LOCALHOST"
        and not os.environ.get("ROS_STATIC_PEERS")
        and not os.environ.get("ROS_DISCOVERY_SERVER")
        and rclpy.get_rmw_implementation_identifier() == "rmw_fastrtps_cpp"
    )


def _discovery_sockets(domain_id: int) -> dict[str, int] | None:
    """The sockets bound to the domain's participant discovery ports: 'socket:[inode]' -> port.

    None if the tables cannot be read whole (a socket left out would be a participant missed).
    """
    first = PORT_BASE + DOMAIN_GAIN * domain_id + METATRAFFIC_UNICAST
    ports = range(first, first + PARTICIPANT_GAIN * MAX_PARTICIPANTS, PARTICIPANT_GAIN)
    sockets: dict[str, int] = {}
    for table in ("/proc/net/udp", "/proc/net/udp6"):
        if table.endswith("6") and not os.path.exists(table):
            continue  # no IPv6 on this machine: no IPv6 sockets either
        try:
            with open(table) as lines:
                next(lines)  # the header
                for line in lines:
                    fields = line.split()
                    port = int(fields[1].rsplit(":", 1)[1], 16)
                    if port in ports:
                        sockets[f"socket:[{fields[9]}]"] = port
        except (OSError, ValueError, IndexError, StopIteration):
            return None
    return sockets


def _owners(sockets: set[str]) -> Counter[int] | None:
    """Per process id, how many of these sockets it holds; None if one has no owner found."""
    owners, unowned = _holders(sockets)
    return None if unowned else owners


def _holders(sockets: set[str]) -> tuple[Counter[int], set[str]]:
    """Per process id, how many of these sockets it holds; and the sockets no owner was
    found for (all of them without /proc)."""
    owners: Counter[int] = Counter()
    sockets = set(sockets)
    try:
        processes = list(os.scandir("/proc"))
    except OSError:  # no /proc: nothing can be known
        return owners, sockets
    for entry in processes:
        if not sockets:
            break
        if not entry.name.isdigit():
            continue
        try:
            descriptors = os.listdir(f"/proc/{entry.name}/fd")
        except OSError:  # gone meanwhile, or another user's
            continue
        for fd in descriptors:
            try:
                target = os.readlink(f"/proc/{entry.name}/fd/{fd}")
            except OSError:
                continue
            if target in sockets:
                sockets.discard(target)
                owners[int(entry.name)] += 1
    return owners, sockets
