"""The daemon's client side: what the lists, TAB completion and `ros2 daemon` ask it.

It loads no rclpy: a question over the daemon's socket and a JSON answer (protocol.py). A list
starts the daemon when none runs (and answers itself that time); ``--no-daemon`` bypasses it.
A command that names a node or topic the complete graph does not hold discovers for itself, so
that it waits for it as it does without a daemon (NotInAnswer).
"""

from __future__ import annotations

import contextlib
import os
import sys
import time
from types import SimpleNamespace
from typing import Any

from ros2cmd.daemon.protocol import ANSWER_WAIT, CREDENTIALS, peer_is_this_user, socket_address
from ros2cmd.errors import ToolError
from ros2cmd.graph import VisibleNames, split_node_name
from ros_tutorials_common.dds import apply_dds_defaults, environment_problem

# json, socket and subprocess are imported where the asking uses them.

ASK_TIMEOUT = ANSWER_WAIT + 3.0  # what a list waits for the daemon's answer, at most
START_TIMEOUT = 10.0  # `ros2 daemon start|stop` (ros2cli: 10 s)
MAX_MESSAGE = 16 * 1024 * 1024
# Set (to anything but empty) the lists do not use the daemon, as with --no-daemon: the
# tests' default (tests/conftest.py), so that they see direct discovery unless they ask.
NO_DAEMON_VARIABLE = "ROS_TUTORIALS_NO_DAEMON"


def use_daemon(no_daemon: bool) -> bool:
    return not no_daemon and not os.environ.get(NO_DAEMON_VARIABLE)


def name_holder() -> str | None:
    """Who holds this user's daemon name, if another user's process does (it took the name
    first, so no daemon of this user can bind it): "uid 65534 (nobody), pid 4242 (python3)";
    None if the name is free or this user's daemon holds it.

    A holder that listens and accepts says who it is on connect (SO_PEERCRED); one that
    only bound the name, or lets connections wait, is found in /proc/net/unix and, where
    this user may look, among the processes' open files.
    """
    import socket

    address = socket_address()
    try:
        with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as connection:
            connection.settimeout(2.0)
            connection.connect(address)
            credentials = connection.getsockopt(
                socket.SOL_SOCKET, socket.SO_PEERCRED, CREDENTIALS.size
            )
            pid, uid, _gid = CREDENTIALS.unpack(credentials)
            return None if uid == os.getuid() else _process(pid, uid)
    except OSError:  # a free name is refused too; a full backlog times out
        pass
    inodes = _bound_inodes(address)
    if not inodes:
        return None
    pid = _socket_owner(inodes)
    if pid is None:
        return "a process this user may not look into, which does not answer"
    uid = _process_uid(pid)
    return None if uid == os.getuid() else _process(pid, uid)


def _bound_inodes(address: str) -> set[str]:
    """The inodes of the Unix sockets named by an abstract ADDRESS (/proc/net/unix): the
    bound one, and those of connections waiting to be accepted."""
    shown = "@" + address[1:]
    found = set()
    with contextlib.suppress(OSError), open("/proc/net/unix") as table:
        for line in table:
            fields = line.split(maxsplit=7)
            if len(fields) == 8 and fields[7].rstrip("\n") == shown:
                found.add(fields[6])
    return found


def _socket_owner(inodes: set[str]) -> int | None:
    """The process that has one of the sockets INODES open, among those this user may look
    into."""
    wanted = {f"socket:[{inode}]" for inode in inodes}
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit():
            continue
        with contextlib.suppress(OSError):
            for fd in os.scandir(f"/proc/{entry.name}/fd"):
                with contextlib.suppress(OSError):
                    if os.readlink(fd.path) in wanted:
                        return int(entry.name)
    return None


def _process_uid(pid: int) -> int | None:
    with contextlib.suppress(OSError, ValueError, IndexError), open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("Uid:"):
                return int(line.split()[1])
    return None


def _process(pid: int, uid: int | None) -> str:
    """'uid 65534 (nobody), pid 4242 (python3)'."""
    import pwd

    user = "uid ?"
    if uid is not None:
        user = f"uid {uid}"
        with contextlib.suppress(KeyError):
            user += f" ({pwd.getpwuid(uid).pw_name})"
    name = ""
    with contextlib.suppress(OSError), open(f"/proc/{pid}/comm") as comm:
        name = f" ({comm.read().strip()})"
    return f"{user}, pid {pid}{name}"


def held_by_another_user(holder: str) -> str:
    return (
        f"another user's process holds this daemon's name ({holder}), so no daemon of yours "
        "can start with these DDS settings; the lists discover for themselves"
    )


def _request(question: dict[str, Any], timeout: float) -> dict[str, Any] | None:
    """One question to the running daemon and its answer; None if none answers."""
    import json
    import socket

    try:
        with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as connection:
            connection.settimeout(timeout)
            connection.connect(socket_address())
            if not peer_is_this_user(connection):  # another user's process took the name
                return None
            connection.sendall(json.dumps(question).encode() + b"\n")
            connection.shutdown(socket.SHUT_WR)
            data = b""
            while chunk := connection.recv(65536):
                data += chunk
                if len(data) > MAX_MESSAGE:
                    return None
        return json.loads(data)
    except (OSError, ValueError):
        return None


def running_pid() -> int | None:
    """The running daemon's process id; None if none answers."""
    answer = _request({"ask": "ping"}, timeout=2.0) or {}
    return answer.get("pid") if answer.get("pong") is True else None


def is_running() -> bool:
    return running_pid() is not None


def spawn() -> None:
    """Start a daemon in the background, in a session of its own (a Ctrl-C in this terminal
    is not for it), with this environment and the DDS defaults. If another one wins the
    race to the socket, this one ends at once."""
    import subprocess

    env = apply_dds_defaults(dict(os.environ))
    subprocess.Popen(
        [sys.executable, "-m", "ros2cmd.daemon.server"],
        stdin=subprocess.DEVNULL,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        env=env,
        start_new_session=True,
        close_fds=True,
        cwd="/",
    )


class NotInAnswer(Exception):
    """What the command names is not in the daemon's answer: it discovers for itself."""


def _names_and_types(entries: Any) -> list[tuple[str, list[str]]]:
    return [(name, list(types)) for name, types in entries]


class _Names:
    """The daemon's names, with the methods of an rclpy node that the commands call."""

    def __init__(self, answer: dict[str, Any]) -> None:
        self._answer = answer

    def _node_info(self, name: str, namespace: str, kind: str) -> list[tuple[str, list[str]]]:
        info = self._answer.get("node_info") or {}
        if info.get("node") != [name, namespace]:
            raise NotInAnswer(f"node {namespace}/{name}")
        return _names_and_types(info[kind])

    def get_subscriber_names_and_types_by_node(self, name: str, namespace: str) -> list:
        return self._node_info(name, namespace, "subscribers")

    def get_publisher_names_and_types_by_node(self, name: str, namespace: str) -> list:
        return self._node_info(name, namespace, "publishers")

    def get_service_names_and_types_by_node(self, name: str, namespace: str) -> list:
        return self._node_info(name, namespace, "service_servers")

    def get_client_names_and_types_by_node(self, name: str, namespace: str) -> list:
        return self._node_info(name, namespace, "service_clients")

    def _endpoints(self, topic: str, kind: str) -> list[SimpleNamespace]:
        info = self._answer.get("topic_info") or {}
        if info.get("topic") != topic:
            raise NotInAnswer(f"topic {topic}")
        return [SimpleNamespace(**endpoint) for endpoint in info[kind]]

    def get_publishers_info_by_topic(self, topic: str) -> list[SimpleNamespace]:
        """Each publisher's node_name, node_namespace and topic_type (what `topic info` counts)."""
        return self._endpoints(topic, "publishers")

    def get_subscriptions_info_by_topic(self, topic: str) -> list[SimpleNamespace]:
        return self._endpoints(topic, "subscriptions")

    def get_node_names_and_namespaces(self) -> list[tuple[str, str]]:
        return [(name, namespace) for name, namespace in self._answer["nodes"]]

    def get_topic_names_and_types(self) -> list[tuple[str, list[str]]]:
        return [(name, list(types)) for name, types in self._answer["topics"]]

    def get_service_names_and_types(self) -> list[tuple[str, list[str]]]:
        return [(name, list(types)) for name, types in self._answer["services"]]


class DaemonAnswer(VisibleNames):
    """The daemon's complete answer, with the methods of graph.Graph that the lists use
    (and as ``node`` the names an rclpy node would give, hidden ones too)."""

    finished = False

    def __init__(self, answer: dict[str, Any]) -> None:
        self._answer = answer
        self.node = _Names(answer)

    def settle(self) -> None:
        """Complete already: the daemon answered only once it was."""

    def finish(self) -> None:
        self.finished = True

    def action_types(self) -> dict[str, list[str]]:
        return {name: list(types) for name, types in self._answer["actions"]}

    def node_actions(self, name: str, namespace: str) -> tuple[list, list]:
        return (
            self.node._node_info(name, namespace, "action_servers"),
            self.node._node_info(name, namespace, "action_clients"),
        )

    def wait_for(self, condition: Any, what: str, timeout: float | None = None) -> Any:
        """condition()'s answer now: the graph is complete, so something it lacks is not
        there yet, and only a command's own node can wait for it (NotInAnswer)."""
        result = condition()
        if not result:
            raise NotInAnswer(what)
        return result

    def close(self) -> None:
        pass


def ask_names(timeout: float) -> dict[str, Any] | None:
    """What the running daemon's graph holds now, complete or not (TAB completion's names:
    ros2cmd/completion.py); None if none answers within TIMEOUT. Starts no daemon."""
    answer = _request({"ask": "names"}, timeout=timeout)
    return answer if answer is not None and "topics" in answer else None


def ask_parameters(node: str, timeout: float) -> list[str]:
    """A node's parameter names, asked through the running daemon (TAB completion); [] if no
    daemon answers, or the node does not within TIMEOUT. Starts no daemon."""
    question = {"ask": "parameters", "node": node, "timeout": timeout * 0.8}
    answer = _request(question, timeout=timeout) or {}
    names = answer.get("parameters")
    return [name for name in names if isinstance(name, str)] if isinstance(names, list) else []


def about_node(full_name: str) -> dict[str, Any]:
    """What ask_graph asks about a node (`node info NAME`)."""
    namespace, name = split_node_name(full_name)
    return {"node": [name, namespace]}


def ask_graph(about: dict[str, Any] | None = None) -> DaemonAnswer | None:
    """The daemon's complete answer; None (the list discovers for itself) if no daemon runs,
    in which case one is started for the next list, or if it could not vouch for one.

    ``about`` asks for more: {"node": [name, namespace]} that node's endpoints (`node info`),
    {"topic": name} the topic's publishers and subscriptions (`topic info`)."""
    answer = _request({"ask": "graph", **(about or {})}, timeout=ASK_TIMEOUT)
    if answer is None:
        with contextlib.suppress(OSError):
            spawn()
        return None
    if not answer.get("complete"):
        return None
    return DaemonAnswer(answer)


def _wait_until(condition: Any, timeout: float) -> bool:
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


def start() -> bool:
    """Start a daemon unless one runs; False if one ran already. ToolError if the DDS
    setting cannot start a node, or the daemon did not answer within START_TIMEOUT."""
    problem = environment_problem()
    if problem:  # the daemon's node could not start
        raise ToolError(problem)
    if is_running():
        return False
    holder = name_holder()
    if holder is not None:
        raise ToolError(held_by_another_user(holder))
    spawn()
    if not _wait_until(is_running, START_TIMEOUT):
        holder = name_holder()  # took the name meanwhile
        if holder is not None:
            raise ToolError(held_by_another_user(holder))
        raise ToolError(f"the daemon did not start within {START_TIMEOUT:g} s")
    return True


def stop() -> bool:
    """Stop the running daemon; False if none ran. ToolError if it did not end in time."""
    stopped = _stop()
    if stopped is None:
        return False
    if not stopped:
        raise ToolError(f"the daemon did not stop within {START_TIMEOUT:g} s")
    return True


def _stop() -> bool | None:
    """Ask the daemon to stop and wait until its process has ended: None if none ran, False
    if it did not end within START_TIMEOUT."""
    pid = running_pid()
    if pid is None or _request({"ask": "stop"}, timeout=START_TIMEOUT) is None:
        return None
    return _wait_until(lambda: not _alive(pid), START_TIMEOUT)


def _alive(pid: int) -> bool:
    """Whether the process runs (a zombie waiting for its parent has ended)."""
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().rsplit(")", 1)[1].split()[0] != "Z"
    except (OSError, IndexError):
        return False


def stop_quietly() -> None:
    """Stop this environment's daemon if one runs, and wait until it has ended."""
    _stop()
