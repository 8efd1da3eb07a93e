"""What the daemon and its clients share: the socket's name and who may be at its other end.

One daemon per user, DDS setting (domain id, discovery range, peers, RMW, profile) and
installation: its socket's name is made from them. The socket is an abstract one (Linux): no
file that can be removed while the daemon lives on, a name that goes when the daemon's process
does, and one that only one process can bind, so that binding it is the lock that lets only one
daemon serve. An abstract socket has no file permissions: each side checks the other's user
(SO_PEERCRED), so the daemon answers only its own user and a list asks only its user's daemon.
A question is one JSON object and a newline; the answer one JSON object.
"""

from __future__ import annotations

import os
import struct
import sys
from typing import TYPE_CHECKING

from ros_tutorials_common.dds import apply_dds_defaults

if TYPE_CHECKING:
    import socket

# How long the daemon waits for a process it counted to be heard from (one that has just
# started) before it tells the list to discover for itself.
ANSWER_WAIT = 2.0
# The environment that decides which graph a node sees (and which code answers).
SETTINGS = (
    "ROS_DOMAIN_ID",
    "ROS_AUTOMATIC_DISCOVERY_RANGE",
    "ROS_STATIC_PEERS",
    "ROS_LOCALHOST_ONLY",
    "RMW_IMPLEMENTATION",
    "FASTRTPS_DEFAULT_PROFILES_FILE",
    "FASTDDS_BUILTIN_TRANSPORTS",
    "ROS_DISCOVERY_SERVER",
)


def socket_address() -> str:
    """The abstract socket of the daemon for this user, this environment's DDS settings and
    this installation."""
    import hashlib
    import json

    env = apply_dds_defaults(dict(os.environ))
    key = json.dumps([sys.prefix, *(env.get(name, "") for name in SETTINGS)])
    digest = hashlib.sha256(key.encode()).hexdigest()[:16]
    domain = env.get("ROS_DOMAIN_ID", "0")
    return f"\0ros_tutorials_daemon_{os.getuid()}_domain{domain}-{digest}"


def peer_is_this_user(connection: socket.socket) -> bool:
    """Whether the process at the other end of a Unix socket runs as this user."""
    import socket

    credentials = connection.getsockopt(socket.SOL_SOCKET, socket.SO_PEERCRED, CREDENTIALS.size)
    _pid, uid, _gid = CREDENTIALS.unpack(credentials)
    return uid == os.getuid()


CREDENTIALS = struct.Struct("3i")  # struct ucred: pid, uid, gid
