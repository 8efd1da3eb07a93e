"""The daemon itself: one hidden graph node (``_ros2cli_daemon_...``) that the lists ask.

A list that starts its own node waits for discovery every time (graph.Graph.settle). The
daemon, like ros2cli's, is a background process that holds one node, which stays up to date,
and answers `node list`, `topic list`, `service list`, `action list`, `topic|service find`,
`node info`, `topic info` (not -v) and `topic|service type` over a Unix socket (only this
user's processes are answered: protocol.py): the names, and for `node info` the node's
endpoints and for `topic info` the topic's, as ros2cli's daemon serves the graph API. It ends
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

TAB completion (ros2cmd/completion.py) asks it too: for the names its graph holds now, complete
or not, and for a node's parameter names.
"""

from __future__ import annotations

import contextlib
import math
import os
import signal
import time
from collections import Counter
from typing import TYPE_CHECKING, Any

from ros2cmd.daemon.protocol import ANSWER_WAIT, peer_is_this_user, socket_address
from ros2cmd.errors import ToolError
from ros_tutorials_common.dds import apply_dds_defaults

if TYPE_CHECKING:
    import socket

IDLE_TIMEOUT = 2 * 60 * 60.0  # s without a question before the daemon ends (as ros2cli's)
ANSWER_POLL = 0.02
# A node's parameter names (TAB completion): the longest the daemon waits for the node's
# answer, and how many nodes' clients it keeps.
PARAMETERS_WAIT = 0.5
MAX_PARAMETER_CLIENTS = 32


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
                        if not peer_is_this_user(connection):
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
    """The daemon's process (`python -m ros2cmd.daemon.server`, started by spawn())."""
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
