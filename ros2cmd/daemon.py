"""`ros2 daemon start|stop|status`, and the daemon: one graph node that the lists ask.

(About 600 lines, one subject: the daemon's client side, `ros2 daemon`, and the daemon itself,
whose questions and answers must change together.)

A list that starts its own node waits for discovery every time (graph.Graph.settle). The
daemon, like ros2cli's, is a background process that holds one hidden node
(``_ros2cli_daemon_...``), which stays up to date, and answers `node list`, `topic list`,
`service list`, `action list`, `topic|service find`, `node info`, `topic info` (not -v) and
`topic|service type` over a Unix socket (only this user's processes are answered, see below):
the names, and for `node info` the node's endpoints and for `topic info` the topic's, as
ros2cli's daemon serves the graph API. A command that names a node or topic the complete
graph does not hold discovers for itself, so that it waits for it as it does without a daemon
(NotInAnswer). The client side loads no rclpy: a question and a JSON answer. A list starts the
daemon when none runs (and answers itself that time); ``--no-daemon`` bypasses it; it ends
after IDLE_TIMEOUT without a question (ros2cli's 2 hours).

ros2cli's daemon answers from whatever its graph holds, so it can miss a node that has just
started or list one that is gone (ros2cli#672). This one answers only once its graph is
complete by the lists' own rule (graph.Graph.settle), read at the moment of the question:
every process that holds a participant on this machine (local_participants.py) has been
heard from, exactly, each participant's announced nodes and endpoints are in the graph, and
no participant of a process that has ended is left in it (one killed by SIGKILL stays in
DDS's graph until its lease runs out, 20 s). Otherwise it says why not, and the list
discovers for itself. So it serves only where the count works: the default
ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST with Fast DDS.

One daemon per user, DDS setting (domain id, discovery range, peers, RMW, profile) and
installation: its socket's name is made from them. The socket is an abstract one (Linux): no
file that can be removed while the daemon lives on, a name that goes when the daemon's process
does, and one that only one process can bind, so that binding it is the lock that lets only one
daemon serve. An abstract socket has no file permissions: each side checks the other's user
(SO_PEERCRED), so the daemon answers only its own user and a list asks only its user's daemon.

TAB completion (ros2cmd/completion.py) asks it too: for the names its graph holds now, complete
or not (``ask_names``), and for a node's parameter names (``ask_parameters``).
"""

from __future__ import annotations

import argparse
import contextlib
import math
import os
import signal
import struct
import sys
import time
from collections import Counter
from types import SimpleNamespace
from typing import TYPE_CHECKING, Any

from ros2cmd.errors import ToolError
from ros2cmd.graph import VisibleNames, split_node_name
from ros2cmd.sub_verbs import VERB_HELP
from ros_tutorials_common.dds import apply_dds_defaults, environment_problem

if TYPE_CHECKING:
    import socket

# hashlib, json, socket, subprocess and selectors are imported where the asking and the serving
# use them: building the parser (`ros2 -h`) only registers the verb.

IDLE_TIMEOUT = 2 * 60 * 60.0  # s without a question before the daemon ends (as ros2cli's)
# How long the daemon waits for a process it counted to be heard from (one that has just
# started) before it tells the list to discover for itself.
ANSWER_WAIT = 2.0
ANSWER_POLL = 0.02
ASK_TIMEOUT = ANSWER_WAIT + 3.0  # what a list waits for the daemon's answer, at most
START_TIMEOUT = 10.0  # `ros2 daemon start|stop` (ros2cli: 10 s)
# A node's parameter names (TAB completion): the longest the daemon waits for the node's
# answer, and how many nodes' clients it keeps.
PARAMETERS_WAIT = 0.5
MAX_PARAMETER_CLIENTS = 32
MAX_MESSAGE = 16 * 1024 * 1024
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
# Set (to anything but empty) the lists do not use the daemon, as with --no-daemon: the
# tests' default (tests/conftest.py), so that they see direct discovery unless they ask.
NO_DAEMON_VARIABLE = "ROS_TUTORIALS_NO_DAEMON"


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


def _peer_is_this_user(connection: socket.socket) -> bool:
    """Whether the process at the other end of a Unix socket runs as this user."""
    import socket

    credentials = connection.getsockopt(socket.SOL_SOCKET, socket.SO_PEERCRED, _CREDENTIALS.size)
    _pid, uid, _gid = _CREDENTIALS.unpack(credentials)
    return uid == os.getuid()


_CREDENTIALS = struct.Struct("3i")  # struct ucred: pid, uid, gid


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
                socket.SOL_SOCKET, socket.SO_PEERCRED, _CREDENTIALS.size
            )
            pid, uid, _gid = _CREDENTIALS.unpack(credentials)
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


def _held_by_another_user(holder: str) -> str:
    return (
        f"another user's process holds this daemon's name ({holder}), so no daemon of yours "
        "can start with these DDS settings; the lists discover for themselves"
    )


def use_daemon(no_daemon: bool) -> bool:
    return not no_daemon and not os.environ.get(NO_DAEMON_VARIABLE)


# The client side: what the lists and `ros2 daemon` do.


def _request(question: dict[str, Any], timeout: float) -> dict[str, Any] | None:
    """One question to the running daemon and its answer; None if none answers."""
    import json
    import socket

    try:
        with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as connection:
            connection.settimeout(timeout)
            connection.connect(socket_address())
            if not _peer_is_this_user(connection):  # another user's process took the name
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
        [sys.executable, "-m", "ros2cmd.daemon"],
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


def start_command() -> None:
    problem = environment_problem()
    if problem:  # the daemon's node could not start
        raise ToolError(problem)
    if is_running():
        print("The daemon is already running")
        return
    holder = name_holder()
    if holder is not None:
        raise ToolError(_held_by_another_user(holder))
    spawn()
    if not _wait_until(is_running, START_TIMEOUT):
        holder = name_holder()  # took the name meanwhile
        if holder is not None:
            raise ToolError(_held_by_another_user(holder))
        raise ToolError(f"the daemon did not start within {START_TIMEOUT:g} s")
    print("The daemon has been started")


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


def stop_command() -> None:
    stopped = _stop()
    if stopped is None:
        print("The daemon is not running")
    elif not stopped:
        raise ToolError(f"the daemon did not stop within {START_TIMEOUT:g} s")
    else:
        print("The daemon has been stopped")


def stop_quietly() -> None:
    """Stop this environment's daemon if one runs, and wait until it has ended."""
    _stop()


def status_command() -> None:
    if is_running():
        print("The daemon is running")
        return
    print("The daemon is not running")
    holder = name_holder()
    if holder is not None:
        print(f"warning: {_held_by_another_user(holder)}", file=sys.stderr)


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("daemon", help=VERB_HELP["daemon"])
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name, run, text in (
        ("start", start_command, "Start the daemon if it isn't running"),
        ("status", status_command, "Output the status of the daemon"),
        ("stop", stop_command, "Stop the daemon if it is running"),
    ):
        p = sub.add_parser(name, help=text)
        p.set_defaults(offline=True, run=lambda _graph, _args, run=run: run())


# The daemon itself.


class Daemon:
    """The graph node, the listening socket, and the answers."""

    def __init__(self, listener: socket.socket) -> None:
        from ros2cmd.graph import Graph  # rclpy: only in the daemon, not in its clients

        self.listener = listener
        self.graph = Graph()
        self.domain_id = self.graph.node.context.get_domain_id()
        self.last_question = time.monotonic()
        self.parameter_clients: dict[str, Any] = {}  # node -> its list_parameters client

    def serve(self) -> None:
        import selectors

        with selectors.DefaultSelector() as selector:
            selector.register(self.listener, selectors.EVENT_READ)
            while self.graph.node.context.ok():
                if time.monotonic() - self.last_question > IDLE_TIMEOUT:
                    return
                if not selector.select(timeout=1.0):
                    continue
                with contextlib.suppress(BlockingIOError):
                    connection, _ = self.listener.accept()
                    with connection:
                        if not _peer_is_this_user(connection):
                            continue
                        if not self._answer(connection):
                            return

    def _answer(self, connection: socket.socket) -> bool:
        """Answer one question; False if it was to stop."""
        import json

        self.last_question = time.monotonic()
        connection.settimeout(2.0)
        try:
            data = b""
            while not data.endswith(b"\n") and len(data) < 65536:
                chunk = connection.recv(65536)
                if not chunk:
                    break
                data += chunk
            asked = json.loads(data)
            question = asked.get("ask")
        except (OSError, ValueError, AttributeError):
            return True
        keep_going = question != "stop"
        if question == "ping":
            answer: dict[str, Any] = {"pong": True, "pid": os.getpid()}
        elif question == "stop":
            answer = {"stopping": True}
        elif question == "graph":
            answer = self.graph_answer(asked)
        elif question == "names":
            answer = self.names_answer()
        elif question == "parameters":
            answer = self.parameters_answer(asked.get("node"), asked.get("timeout"))
        else:
            answer = {"error": f"unknown question {question!r}"}
        with contextlib.suppress(OSError):
            connection.sendall(json.dumps(answer).encode())
        return keep_going

    def graph_answer(self, asked: dict[str, Any] | None = None) -> dict[str, Any]:
        """The lists' names, once the graph is complete; or why it is not. With a node or a
        topic asked about (ask_graph), its endpoints too, if the graph holds it."""
        deadline = time.monotonic() + ANSWER_WAIT
        while True:
            verdict = self.complete()
            if verdict is None:
                break
            final, why = verdict
            if final or time.monotonic() > deadline:
                return {"complete": False, "why": why}
            time.sleep(ANSWER_POLL)
        answer = {"complete": True, **self.names_answer()}
        asked = asked or {}
        about_node, about_topic = asked.get("node"), asked.get("topic")
        if _is_pair_of_names(about_node) and tuple(about_node) in answer["nodes"]:
            with contextlib.suppress(RuntimeError, ValueError):  # it has just gone
                answer["node_info"] = self.node_info(*about_node)
        if isinstance(about_topic, str) and about_topic in dict(answer["topics"]):
            with contextlib.suppress(RuntimeError, ValueError):
                answer["topic_info"] = self.topic_info(about_topic)
        return answer

    def names_answer(self) -> dict[str, Any]:
        """Every name the graph holds now, hidden ones too (the client filters as asked)."""
        node = self.graph.node
        return {
            "nodes": node.get_node_names_and_namespaces(),
            "topics": node.get_topic_names_and_types(),
            "services": node.get_service_names_and_types(),
            "actions": sorted(self.graph.action_types().items()),
        }

    def parameters_answer(self, node: Any, timeout: Any) -> dict[str, Any]:
        """A node's parameter names, if it answers within TIMEOUT (at most PARAMETERS_WAIT):
        TAB completion's `ros2 param get NODE <TAB>`. Its client stays for the next question
        (a new one must first be matched with the node's service, which takes longer)."""
        from rcl_interfaces.srv import ListParameters

        if not isinstance(node, str) or not isinstance(timeout, (int, float)):
            return {"error": "parameters: a node name and a timeout"}
        timeout = min(max(float(timeout), 0.0), PARAMETERS_WAIT) if math.isfinite(timeout) else 0.0
        node = "/" + node.strip("/")
        present = set(self.graph.node_names())
        for gone in [name for name in self.parameter_clients if name not in present]:
            self.graph.node.destroy_client(self.parameter_clients.pop(gone))
        if node not in present:
            return {"parameters": []}
        client = self.parameter_clients.get(node)
        if client is None:
            if len(self.parameter_clients) >= MAX_PARAMETER_CLIENTS:
                oldest = next(iter(self.parameter_clients))
                self.graph.node.destroy_client(self.parameter_clients.pop(oldest))
            client = self.graph.node.create_client(ListParameters, f"{node}/list_parameters")
            self.parameter_clients[node] = client
        calls: list[Any] = []

        def answered() -> bool:
            if not calls and client.service_is_ready():
                calls.append(client.call_async(ListParameters.Request()))
            return bool(calls) and calls[0].done()

        with contextlib.suppress(ToolError):
            self.graph.wait_for(answered, "", timeout)
        if not calls or not calls[0].done() or calls[0].result() is None:
            if calls:
                client.remove_pending_request(calls[0])
            return {"parameters": []}
        return {"parameters": sorted(calls[0].result().result.names)}

    def node_info(self, name: str, namespace: str) -> dict[str, Any]:
        """What `node info` prints of a node: its endpoints by kind, (name, types) each."""
        node = self.graph.node
        action_servers, action_clients = self.graph.node_actions(name, namespace)
        return {
            "node": [name, namespace],
            "subscribers": node.get_subscriber_names_and_types_by_node(name, namespace),
            "publishers": node.get_publisher_names_and_types_by_node(name, namespace),
            "service_servers": node.get_service_names_and_types_by_node(name, namespace),
            "service_clients": node.get_client_names_and_types_by_node(name, namespace),
            "action_servers": action_servers,
            "action_clients": action_clients,
        }

    def topic_info(self, topic: str) -> dict[str, Any]:
        """What `topic info` counts of a topic: its publishers and subscriptions."""
        node = self.graph.node

        def endpoints(found: list) -> list[dict[str, str]]:
            return [
                {
                    "node_name": endpoint.node_name,
                    "node_namespace": endpoint.node_namespace,
                    "topic_type": endpoint.topic_type,
                }
                for endpoint in found
            ]

        return {
            "topic": topic,
            "publishers": endpoints(node.get_publishers_info_by_topic(topic)),
            "subscriptions": endpoints(node.get_subscriptions_info_by_topic(topic)),
        }

    def complete(self) -> tuple[bool, str] | None:
        """None if the graph is complete now; else (whether waiting cannot help, why not)."""
        from ros2cmd.local_participants import local_participants, process_of

        graph = self.graph
        if not graph.discovery.available:
            return True, "no ros_discovery_info to compare with"
        expected = local_participants(self.domain_id)
        if expected is None:
            return True, "this machine cannot say which processes hold a participant"
        seen = Counter(process_of(prefix) for prefix in graph.participants())
        if seen != expected:
            gone = [pid for pid in seen if pid is None or seen[pid] > expected[pid]]
            if gone:  # ended (it stays until its lease runs out), or another vendor's
                return True, f"participants of processes that are gone or not counted: {gone}"
            return False, "processes not heard from yet"
        graph.discovery.take()
        missing = graph.missing()
        if missing:
            return False, "; ".join(missing[:3])
        # Counted again: a process that made a new participant meanwhile must not pass.
        if local_participants(self.domain_id) != expected:
            return False, "processes changed while looking"
        return None

    def close(self) -> None:
        self.graph.close()


def _is_pair_of_names(value: Any) -> bool:
    return isinstance(value, list) and len(value) == 2 and all(isinstance(v, str) for v in value)


def main() -> int:
    """The daemon's process (`python -m ros2cmd.daemon`, started by spawn())."""
    import socket

    apply_dds_defaults()
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as listener:
        try:
            listener.bind(socket_address())
        except OSError:
            return 0  # another daemon holds the name: that one answers
        listener.listen(16)
        listener.setblocking(False)
        # SIGINT too ends it quietly (rclpy shuts down on SIGTERM; see Graph).
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        daemon = None
        try:
            daemon = Daemon(listener)
            daemon.serve()
        finally:
            if daemon is not None:
                daemon.close()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
