"""The one place that sets this project's DDS defaults.

Fast DDS multicasts discovery on every network interface unless told otherwise. The
tutorials keep their traffic on this machine: ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST,
unless the user has set it (e.g. SUBNET to talk to other machines). Fast DDS also gets this
project's profile (config/fastdds.xml: announce every 0.25 s, so a command started later finds
running nodes quickly) unless the user names another. They must be applied before
rclpy.init(), which is when rcl and Fast DDS read them; the launcher passes them to its children.
"""

from __future__ import annotations

import os
import re
from collections.abc import Mapping, MutableMapping, Sequence
from pathlib import Path
from typing import IO

DDS_DEFAULTS = {
    "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
    # Faster discovery of running nodes by a process that starts later (see the file).
    "FASTRTPS_DEFAULT_PROFILES_FILE": str(Path(__file__).with_name("config") / "fastdds.xml"),
}
# Every RMW accepts domain ids 0..101 (Fast DDS maps them to ports); 0 is everyone's default.
PRIVATE_DOMAIN_IDS = range(1, 102)


# Fast DDS gives domain d the ports from 7400 + 250 * d: above 232 they pass 65535.
MAX_DOMAIN_ID = 232


def domain_id(env: Mapping[str, str] | None = None) -> int | None:
    """ROS_DOMAIN_ID as rcl reads it: 0 when unset or empty; None when rcl would refuse it.

    rcl reads it with C's strtoul, which knows ASCII digits only: Python's int() and
    str.isdigit() also take other scripts' digits (Arabic-Indic, fullwidth), which rcl refuses.
    """
    text = (os.environ if env is None else env).get("ROS_DOMAIN_ID", "").strip()
    if not text:
        return 0
    if not (text.isascii() and text.isdigit()):
        return None
    return int(text)


def domain_id_problem(env: Mapping[str, str] | None = None) -> str | None:
    """What is wrong with ROS_DOMAIN_ID, as one line; None if it can be used (or is unset)."""
    text = (os.environ if env is None else env).get("ROS_DOMAIN_ID", "").strip()
    value = domain_id(env)
    if value is None:
        what = "is not a whole number in ASCII digits"
    elif value > MAX_DOMAIN_ID:
        what = f"is above {MAX_DOMAIN_ID}, the largest domain id Fast DDS can use"
    else:
        return None
    ids = f"0 to {PRIVATE_DOMAIN_IDS[-1]}"
    return f"ROS_DOMAIN_ID={text!r} {what}: use one from {ids} (every RMW takes those)"


def log_dir(env: Mapping[str, str] | None = None) -> Path:
    """Where rcl writes a process's log file: ROS_LOG_DIR, else ROS_HOME/log, else ~/.ros/log."""
    env = os.environ if env is None else env
    if env.get("ROS_LOG_DIR"):
        return Path(os.path.expanduser(env["ROS_LOG_DIR"]))
    home = env.get("ROS_HOME") or os.path.join(os.path.expanduser("~"), ".ros")
    return Path(os.path.expanduser(home)) / "log"


def log_dir_problem(env: Mapping[str, str] | None = None) -> str | None:
    """What keeps rcl from writing its log file, as one line; None if nothing does.

    rclpy.init fails with an RCLError traceback when the directory cannot be created; this
    creates it as rcl would (so an answer of None is true), and checks it can be written."""
    path = log_dir(env)
    named_by = next(
        (n for n in ("ROS_LOG_DIR", "ROS_HOME") if (os.environ if env is None else env).get(n)),
        "HOME",
    )
    try:
        path.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        reason = "not a directory"
    except OSError as error:
        reason = error.strerror or str(error)
    else:
        if os.access(path, os.W_OK | os.X_OK):
            return None
        reason = "not writable"
    return (
        f"cannot write ROS log files to '{path}' ({named_by}): {reason}; "
        "set ROS_LOG_DIR to a directory you can write"
    )


def peer_name_ok(peer: str) -> bool:
    """An IP address or a host name, by its form only (``999.1.1.1`` is neither: a name
    cannot be all digits and dots)."""
    import ipaddress  # here, as below: every lesson's start imports this module

    try:
        ipaddress.ip_address(peer)
        return True
    except ValueError:
        if re.fullmatch(r"[0-9.]+", peer):
            return False
        return bool(re.fullmatch(r"[A-Za-z0-9]([A-Za-z0-9.-]{0,252})", peer))


def static_peers_problem(env: Mapping[str, str] | None = None) -> str | None:
    """What in ROS_STATIC_PEERS would make creating a node fail (rmw_fastrtps turns each peer
    into the first IPv4 address it resolves to), as one line; None if nothing would."""
    text = (os.environ if env is None else env).get("ROS_STATIC_PEERS", "")
    for peer in (p.strip() for p in text.split(";")):
        if not peer:
            continue
        if not peer_name_ok(peer):
            return f"ROS_STATIC_PEERS: {peer!r} is not an IP address or a host name"
        import ipaddress
        import socket

        try:
            if ipaddress.ip_address(peer).version == 4:
                continue
        except ValueError:  # a host name
            pass
        else:
            return f"ROS_STATIC_PEERS: {peer!r} is an IPv6 address; Fast DDS takes IPv4 peers"
        try:
            socket.getaddrinfo(peer, None, socket.AF_INET)  # what Fast DDS does with it next
        except (OSError, UnicodeError):
            return (
                f"ROS_STATIC_PEERS: {peer!r} does not resolve to an IPv4 address, "
                "which Fast DDS needs for each peer"
            )
    return None


def environment_problem(env: Mapping[str, str] | None = None) -> str | None:
    """The first thing in the environment that would make rclpy.init or the first node fail
    (or Fast DDS print its own lines), as one line; None if there is nothing."""
    return domain_id_problem(env) or log_dir_problem(env) or static_peers_problem(env)


def apply_dds_defaults(env: MutableMapping[str, str] | None = None) -> MutableMapping[str, str]:
    """Fill in the DDS defaults the user has not set; return the environment."""
    if env is None:
        env = os.environ
    for name, value in DDS_DEFAULTS.items():
        env.setdefault(name, value)
    return env


def claim_private_domain_id(ids: Sequence[int] = PRIVATE_DOMAIN_IDS) -> tuple[int, IO[str]]:
    """Claim a ROS_DOMAIN_ID no other test run or benchmark on this machine holds.

    Each id has a lock file; the returned handle holds the lock until it is closed (or the
    process ends), so concurrent runs never see each other's nodes. ``ids``: where to look
    (1 to 101 unless a test needs an id above them).
    """
    import fcntl
    import random
    import tempfile

    lock_dir = Path(tempfile.gettempdir()) / "ros_tutorials_domains"
    lock_dir.mkdir(exist_ok=True)
    candidates = list(ids)
    random.shuffle(candidates)
    for domain_id in candidates:
        handle = open(lock_dir / f"{domain_id}.lock", "w")  # noqa: SIM115 - held by the caller
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            handle.close()
            continue
        return domain_id, handle
    raise RuntimeError(
        f"no free ROS_DOMAIN_ID: every id in {min(ids)}..{max(ids)} is held by another run"
    )
