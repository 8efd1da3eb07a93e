"""What `ros2 doctor` learns from the network itself: interfaces, multicast, DDS announcements.

ros2doctor reads the interfaces through psutil; this environment has only the standard
library, so the same facts come from the kernel: names (if_nameindex), flags, address,
netmask, broadcast and MTU (ioctl), the hardware address (/sys/class/net) and the IPv6
addresses (/proc/net/if_inet6).

Only where the user has set ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET (DDS traffic leaves this
machine anyway) does `ros2 doctor` send or listen on the network: a datagram to DDS's
multicast group that must come back to this machine (as `ros2 multicast send/receive` on
one machine), and listening to the participant announcements (RTPS SPDP) multicast on a
domain's discovery port, which say who is in that domain and from which address.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import select
import socket
import struct
import threading
import time
from dataclasses import dataclass, field

DDS_MULTICAST_GROUP = "239.255.0.1"  # RTPS's default discovery group (Fast DDS's too)
# Below domain 0's ports (7400 + 250 * domain + 0, 1, 10, 11, ...): no DDS participant
# listens there, so the datagram disturbs none.
MULTICAST_TEST_PORT = 7399
PORT_BASE, DOMAIN_GAIN = 7400, 250  # RTPS 9.6.1.1: a domain's multicast discovery port
# A participant announces itself every 3 s (Fast DDS's default leaseAnnouncement): listening
# this long hears every participant of a domain that runs with the defaults.
LISTEN_TIME = 3.2

# ioctl requests (linux/sockios.h) and the interface flags ros2doctor names (net/if.h).
SIOCGIFFLAGS, SIOCGIFADDR, SIOCGIFBRDADDR, SIOCGIFNETMASK, SIOCGIFMTU = (
    0x8913,
    0x8915,
    0x8919,
    0x891B,
    0x8921,
)
FLAG_NAMES = (
    "UP",
    "BROADCAST",
    "DEBUG",
    "LOOPBACK",
    "PTP",
    "NOTRAILERS",
    "RUNNING",
    "NOARP",
    "PROMISC",
    "ALLMULTI",
    "MASTER",
    "SLAVE",
    "MULTICAST",
    "PORTSEL",
    "AUTOMEDIA",
    "DYNAMIC",
)


@dataclass
class Interface:
    """One network interface, with the facts ros2doctor's NETWORK CONFIGURATION lists."""

    device: str
    flags: int = -1
    inet: str | None = None
    netmask: str | None = None
    broadcast: str | None = None
    mtu: int | None = None
    ether: str | None = None
    inet6: list[str] = field(default_factory=list)

    def flag_names(self) -> list[str]:
        return [
            name for bit, name in enumerate(FLAG_NAMES) if self.flags >= 0 and self.flags >> bit & 1
        ]

    @property
    def loopback(self) -> bool:
        return "LOOPBACK" in self.flag_names()

    @property
    def multicast(self) -> bool:
        return "MULTICAST" in self.flag_names()

    def report_items(self) -> list[tuple[str, object]]:
        """ros2doctor's keys, in its order, those without a value left out."""
        items = {
            "inet": self.inet,
            "inet4": [self.inet] if self.inet else None,
            "ether": self.ether,
            "inet6": self.inet6 or None,
            "netmask": self.netmask,
            "device": self.device,
            "flags": f"{self.flags}<{','.join(self.flag_names())}>" if self.flags >= 0 else None,
            "mtu": self.mtu,
            "broadcast": self.broadcast,
        }
        return [(key, value) for key, value in items.items() if value]


def _ioctl(request: int, name: str) -> bytes | None:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        try:
            return fcntl.ioctl(probe.fileno(), request, struct.pack("256s", name.encode()[:15]))
        except OSError:
            return None


def _address(request: int, name: str) -> str | None:
    answer = _ioctl(request, name)
    return socket.inet_ntoa(answer[20:24]) if answer else None


def interfaces() -> list[Interface]:
    """This machine's network interfaces (their order: the kernel's index)."""
    inet6: dict[str, list[str]] = {}
    with contextlib.suppress(OSError), open("/proc/net/if_inet6") as table:
        for line in table:
            fields = line.split()
            if len(fields) == 6:
                address = socket.inet_ntop(socket.AF_INET6, bytes.fromhex(fields[0]))
                scope = f"%{fields[5]}" if address.startswith("fe80") else ""
                inet6.setdefault(fields[5], []).append(address + scope)
    found = []
    for _index, name in socket.if_nameindex():
        interface = Interface(name, inet6=inet6.get(name, []))
        flags = _ioctl(SIOCGIFFLAGS, name)
        if flags:
            interface.flags = struct.unpack("H", flags[16:18])[0]
        interface.inet = _address(SIOCGIFADDR, name)
        if interface.inet:
            interface.netmask = _address(SIOCGIFNETMASK, name)
            interface.broadcast = (
                _address(SIOCGIFBRDADDR, name) if "BROADCAST" in (interface.flag_names()) else None
            )
        mtu = _ioctl(SIOCGIFMTU, name)
        if mtu:
            interface.mtu = struct.unpack("i", mtu[16:20])[0]
        with contextlib.suppress(OSError):
            with open(f"/sys/class/net/{name}/address") as address:
                ether = address.read().strip()
            if ether and ether != "00:00:00:00:00:00":  # loopback's all-zero address
                interface.ether = ether
        found.append(interface)
    return found


def multicast_comes_back(timeout: float = 1.0) -> tuple[bool, str]:
    """Send one datagram to DDS's multicast group and wait for it to come back here.

    Sent with the default TTL of 1 (it does not go past the first router). Coming back shows
    that this machine has a route for multicast and receives the group; whether the network's
    switches pass it to other machines, only `ros2 multicast receive` on another machine shows.
    """
    token = f"ros2 doctor {os.getpid()} {time.monotonic_ns()}".encode()
    try:
        with contextlib.ExitStack() as stack:
            receiver = stack.enter_context(socket.socket(socket.AF_INET, socket.SOCK_DGRAM))
            receiver.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            receiver.bind(("", MULTICAST_TEST_PORT))
            membership = struct.pack(
                "4sl", socket.inet_aton(DDS_MULTICAST_GROUP), socket.INADDR_ANY
            )
            receiver.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
            sender = stack.enter_context(socket.socket(socket.AF_INET, socket.SOCK_DGRAM))
            sent = time.monotonic()
            sender.sendto(token, (DDS_MULTICAST_GROUP, MULTICAST_TEST_PORT))
            deadline = sent + timeout
            while (left := deadline - time.monotonic()) > 0:
                if not select.select([receiver], [], [], left)[0]:
                    break
                data, _sender = receiver.recvfrom(1024)
                if data == token:
                    return True, f"{(time.monotonic() - sent) * 1000:.0f} ms"
    except OSError as error:
        return False, f"{DDS_MULTICAST_GROUP}: {error.strerror or error}"
    return False, f"nothing came back from {DDS_MULTICAST_GROUP} within {timeout:g} s"


def discovery_port(domain_id: int) -> int:
    return PORT_BASE + DOMAIN_GAIN * domain_id


class AnnouncementListener:
    """Listens, in a thread, to the participant announcements multicast in some domains.

    Each RTPS message starts with "RTPS", the protocol version, the vendor id and the
    sender's 12-byte GUID prefix: what a participant is, and (the datagram's source) from
    where. Participants on this machine are heard too, through the loopback of multicast.
    """

    def __init__(self, domain_ids: list[int], duration: float = LISTEN_TIME) -> None:
        self.started = time.monotonic()
        self.duration = duration
        self.heard: dict[int, dict[bytes, str]] = {d: {} for d in domain_ids}  # prefix -> addr
        self.failed: str | None = None
        self._sockets: dict[socket.socket, int] = {}
        self._stop = threading.Event()
        membership = struct.pack("4sl", socket.inet_aton(DDS_MULTICAST_GROUP), socket.INADDR_ANY)
        try:
            for domain_id in domain_ids:
                listener = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
                self._sockets[listener] = domain_id
                # Fast DDS binds these ports with SO_REUSEADDR: every member gets each datagram.
                listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
                listener.bind(("", discovery_port(domain_id)))
                listener.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
        except OSError as error:
            self.failed = str(error.strerror or error)
            self.close()
            return
        self._thread = threading.Thread(target=self._listen, daemon=True)
        self._thread.start()

    def _listen(self) -> None:
        deadline = self.started + self.duration
        while not self._stop.is_set() and (left := deadline - time.monotonic()) > 0:
            ready, _, _ = select.select(list(self._sockets), [], [], min(left, 0.1))
            for listener in ready:
                with contextlib.suppress(OSError):
                    data, (address, _port) = listener.recvfrom(65536)
                    if data[:4] == b"RTPS" and len(data) >= 20:
                        self.heard[self._sockets[listener]][bytes(data[8:20])] = address

    def finish(self, wait: bool) -> None:
        """Stop listening: at once, or (wait) once the whole listening time has passed."""
        if self._sockets:
            if not wait:
                self._stop.set()
            self._thread.join()
        self.close()

    def close(self) -> None:
        for listener in self._sockets:
            listener.close()
        self._sockets = {}
