"""The ROS graph as the command-line tools see it: one hidden node, and waiting that is bounded.

(About 500 lines, one subject: the Graph's waits and the complete snapshot they lead to are
read together; discovery.py and local_participants.py hold what they ask.)

Every command starts one node (its name begins with ``_`` so ``node list`` hides it, as
ros2cli hides its own) and asks the graph. DDS discovery is asynchronous: a node that
is already running shows up in a new process after a few milliseconds, or after the
running participants' next announcement (every 0.25 s with this project's Fast DDS
profile, every 3 s with Fast DDS's default). So a command never sleeps a
fixed time: it polls until what it needs appears (``wait_for``), and reports "unknown
..." only when its timeout has passed.

Listing commands must show everything that was running before they started. Discovery
tells them when that is (``settle``): every running participant has announced itself once
its announcement period (0.25 s here) has passed since ours started (we wait five, and
five after the last participant found: participants are not visible through ROS); or, where
the machine can say which processes hold one (local_participants.py), as soon as each of them
has been heard from, however long its own period (a plain rclpy node without this project's
profile announces every 3 s, and a newcomer may miss its first answer and wait for the next); each
participant's ``ros_discovery_info`` (discovery.py) says which nodes it holds and which
readers and writers each node has; the graph is complete when every participant seen has sent it and
every node and endpoint it names is in our graph. ``snapshot()`` then gives every tool the
same view: nodes, topics with their publishers and subscribers (with node names and QoS),
services and actions with their servers and clients.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any, TypeVar

from ros2cmd.discovery import DISCOVERY_TOPIC, DiscoveryInfo, announcement_period, participant_of
from ros2cmd.errors import ToolError, rclpy_error
from ros2cmd.local_participants import (
    heard_from_all,
    local_participants,
    still_there,
    unexplained,
)
from ros_tutorials_common import bounded, shutdown
from ros_tutorials_common.wait import spin_until

if TYPE_CHECKING:
    from rclpy.qos import QoSProfile

# rclpy (about 0.1 s to load, 0.25 s with rclpy.action) is imported where a command uses it, so
# that help, parsing and the daemon's answers go without it (tests/test_cli_imports.py).

# Set (to a number of seconds), how long a command waits by default for the thing it names to
# appear, instead of 5 s: the tests' setting (tests/conftest.py), on a loaded 2-core machine
# where a new process once did not see a running node within 5 s. --timeout still wins.
TIMEOUT_VARIABLE = "ROS_TUTORIALS_TOOL_TIMEOUT"


def _default_timeout() -> float:
    try:
        seconds = float(os.environ.get(TIMEOUT_VARIABLE, ""))
    except ValueError:
        return 5.0
    return seconds if 0 < seconds < 1e6 else 5.0


DEFAULT_TIMEOUT = _default_timeout()  # how long a command waits for the thing it names to appear
MAX_SETTLE_TIME = 10.0  # the most a listing waits for discovery to complete
POLL_PERIOD = 0.02  # how often a wait looks for what it waits for, at first (wait_for)
# How often settle() looks for new participants: against an announcement period of 0.25 s,
# finding one up to 0.05 s later changes nothing, and each look costs CPU.
SETTLE_POLL_PERIOD = 0.05
ANNOUNCEMENTS = 5  # announcement periods a listing waits for participants to be discovered
# How often a listing that waits for a process the count named counts again (it may have ended).
RECOUNT_PERIOD = 0.25
UNKNOWN_NODE = "_NODE_NAME_UNKNOWN_"  # rmw's name for an endpoint whose node is not known yet

T = TypeVar("T")


def split_node_name(full_name: str) -> tuple[str, str]:
    """'/ns1/topic_publisher' -> ('/ns1', 'topic_publisher'); a bare name is in '/'."""
    full_name = "/" + full_name.strip("/")
    namespace, _, name = full_name.rpartition("/")
    return namespace or "/", name


def join_node_name(namespace: str, name: str) -> str:
    return namespace.rstrip("/") + "/" + name


def absolute_name(name: str) -> str:
    """Topic, service and action names given on the command line are taken from the root."""
    return name if name.startswith("/") else "/" + name


def is_hidden(name: str) -> bool:
    """Names with a part starting with '_' (e.g. an action's /_action/feedback) are internal."""
    return any(part.startswith("_") for part in name.split("/"))


def until_stopped() -> contextlib.AbstractContextManager:
    """For what runs until Ctrl-C (echo, hz, pub -r): that is its normal end, exit status 0.

    Elsewhere Ctrl-C interrupts a command before it has done its job: exit status 130.
    Enter it before printing anything that tells the user the command now runs until
    Ctrl-C ("publishing and latching message. Press ctrl-C to terminate"): a Ctrl-C
    answering that line must find the command already in this state, however late the
    process gets the CPU back after printing. An error the Ctrl-C caused on its way up
    (shutdown.interrupted: rclpy's C++ had called the Python code it interrupted) ends it the
    same way.
    """
    return _UntilStopped()


class _UntilStopped(contextlib.AbstractContextManager):
    def __exit__(self, kind: type | None, error: BaseException | None, tb: object) -> bool:
        if error is None:
            return False
        stopped = (KeyboardInterrupt, *rclpy_error("rclpy.executors", "ExternalShutdownException"))
        return isinstance(error, stopped) or (
            isinstance(error, Exception) and shutdown.interrupted(error)
        )


# Plain classes, not dataclasses: the dataclasses module loads inspect (about 8 ms), which
# every `ros2` command would pay for a snapshot only the graph views take.


class Endpoint:
    """A publisher or subscription: its node's full name ('' while unknown) and its QoS."""

    def __init__(self, node: str, qos: QoSProfile) -> None:
        self.node = node
        self.qos = qos


class TopicInfo:
    def __init__(self, types: list[str]) -> None:
        self.types = types
        self.publishers: list[Endpoint] = []
        self.subscribers: list[Endpoint] = []


class ServiceInfo:
    """A service or an action: its types and the full names of its servers and clients."""

    def __init__(self, types: list[str]) -> None:
        self.types = types
        self.servers: list[str] = []
        self.clients: list[str] = []


class Snapshot:
    """What the graph holds at one moment, the tools' own nodes and hidden names left out."""

    def __init__(
        self,
        nodes: list[str],
        topics: dict[str, TopicInfo],
        services: dict[str, ServiceInfo],
        actions: dict[str, ServiceInfo],
    ) -> None:
        self.nodes = nodes
        self.topics = topics
        self.services = services
        self.actions = actions


def print_names(
    graph: Graph,
    names_and_types: Callable[[], dict[str, list[str]]],
    show_types: bool = False,
    of_type: str | None = None,
) -> None:
    """`list` and `find` of topics, services and actions: once the graph is complete, each
    name (with its types if show_types), or only the names that have the type of_type."""
    graph.settle()
    for name, types in sorted(names_and_types().items()):
        if of_type is None or of_type in types:
            print(f"{name} [{', '.join(types)}]" if show_types else name)


@contextlib.contextmanager
def ctrl_c_deferred() -> Iterator[None]:
    """A Ctrl-C during the block takes effect after it: for short steps that must not be
    cut half-way (creating and destroying the tool's rclpy objects)."""
    pressed = []
    previous = signal.signal(signal.SIGINT, lambda *_: pressed.append(True))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if pressed and callable(previous):
        previous(signal.SIGINT, None)  # Python's default raises KeyboardInterrupt now


class VisibleNames:
    """What a graph holds, hidden names left out as ros2cli does: from ``self.node`` (an rclpy
    node, or the daemon's answer standing in for one)."""

    node: Any

    def node_names(self) -> list[str]:
        names = self.node.get_node_names_and_namespaces()
        return sorted(join_node_name(ns, name) for name, ns in names if not name.startswith("_"))

    def topic_types(self) -> dict[str, list[str]]:
        return {n: t for n, t in self.node.get_topic_names_and_types() if not is_hidden(n)}

    def service_types(self) -> dict[str, list[str]]:
        return {n: t for n, t in self.node.get_service_names_and_types() if not is_hidden(n)}

    def wait_for(self, condition: Callable[[], T], what: str, timeout: float | None = None) -> T:
        """condition()'s first truthy answer (Graph spins for it; the daemon's answer has it
        now or never); ``what`` says what did not come."""
        raise NotImplementedError

    def wait_for_topic_type(self, topic: str) -> str:
        types = self.wait_for(
            lambda: self.topic_types().get(topic),
            f"unknown topic '{topic}': no publisher or subscriber seen",
        )
        return types[0]

    def wait_for_service_type(self, service: str) -> str:
        types = self.wait_for(
            lambda: self.service_types().get(service),
            f"unknown service '{service}': no server seen",
        )
        return types[0]

    def wait_for_node(self, full_name: str) -> str:
        full_name = "/" + full_name.strip("/")
        return self.wait_for(
            lambda: full_name if full_name in self.node_names() else None,
            f"unknown node '{full_name}': not seen in the graph",
        )


class Graph(VisibleNames):
    """One hidden node in a fresh rclpy context, and helpers that wait on the graph."""

    def __init__(self, timeout: float = DEFAULT_TIMEOUT, spin_time: float | None = None):
        self.timeout = timeout
        self.spin_time = spin_time
        self.finished = False  # see finish()
        # SIGTERM only: Ctrl-C stays Python's KeyboardInterrupt and ROS keeps running, so
        # that `action send_goal` can still cancel its goal after it.
        self.incomplete: list[str] = []  # what the last settle() still missed
        # The node is in the graph (a user may be waiting for it to press Ctrl-C) before
        # the executor exists: an executor cut half-way by Ctrl-C complains when collected.
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.node import Node
        from rclpy.signals import SignalHandlerOptions

        from ros_tutorials_common.ros import init

        try:
            with ctrl_c_deferred():
                init(["ros2cmd"], signal_handler_options=SignalHandlerOptions.SIGTERM)
                # No parameter services or rosout: the tool's node should not clutter what
                # it shows.
                self.node = Node(
                    f"_ros2cli_{os.getpid()}", start_parameter_services=False, enable_rosout=False
                )
                self.started = time.monotonic()
                self.executor = SingleThreadedExecutor()
                self.executor.add_node(self.node)
                self.discovery = DiscoveryInfo(self.node)
        except KeyboardInterrupt:  # pressed meanwhile: everything exists, close it first
            self.close()
            raise
        shutdown.count_presses()  # a Ctrl-C lost on its way still ends a wait (see shutdown.py)
        # SIGTERM shuts ROS down (rclpy's handler) and nothing more: a wait for a file's
        # bytes (`rosparam load FIFO`) asks whether it happened.
        bounded.stop_requested = lambda: not self.node.context.ok()

    def close(self) -> None:
        """Destroy the node and shut ROS down; a Ctrl-C meanwhile takes effect afterwards.

        Closing is short, and one interrupted half-way would leave rclpy to complain at exit.
        """
        import rclpy
        from rclpy.signals import uninstall_signal_handlers

        with ctrl_c_deferred():
            if not self.node.context.ok():
                # Shut down by SIGTERM: rclpy's signal thread may still be inside rcl_shutdown
                # (the context reads "down" from its start), and destroying the node beside it
                # is the likely cause of a rare SIGSEGV in destroy_node (`rosbag record -a`
                # after closing its bag). Uninstalling rclpy's handlers first stops that thread
                # (meant to wait for it; the crash is too rare to show the effect in a run).
                uninstall_signal_handlers()
            self.discovery.close()
            self.executor.shutdown()
            self.node.destroy_node()
            rclpy.try_shutdown()

    def __enter__(self) -> Graph:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.close()

    def finish(self) -> None:
        """A one-shot command has its answer: call this just before printing it.

        From then on a Ctrl-C (the user answering the printed line, however late the
        process gets the CPU back) does not make the command "interrupted" (130): its exit
        status stays 0 (see cli.execute). The counterpart of until_stopped. Ctrl-C is ignored
        from here on, before the answer is printed: a Ctrl-C between the printed answer and
        cli.execute's own decision must not end the command with 130.
        """
        self.finished = True
        if threading.current_thread() is threading.main_thread():
            signal.signal(signal.SIGINT, signal.SIG_IGN)

    def spin_once(self, timeout: float = POLL_PERIOD) -> None:
        self.executor.spin_once(timeout_sec=timeout)

    def wait_for(self, condition: Callable[[], T], what: str, timeout: float | None = None) -> T:
        """Spin until condition() gives something truthy and return it; ToolError on timeout."""
        timeout = self.timeout if timeout is None else timeout
        result = spin_until(self.executor, condition, timeout, period=POLL_PERIOD, slow_down=True)
        if not result:
            raise ToolError(f"{what} (waited {timeout:g} s)")
        return result

    def settle(self) -> None:
        """Wait until the graph holds everything that was running when this command started.

        Complete means: every running participant has been heard from, and every participant
        seen has sent its ros_discovery_info, and every node and endpoint it announced is in
        our graph. Who runs is known where local_participants() can count the processes that
        hold a participant on this machine: then the wait lasts until each of them has been
        heard from (usually at once), however long its own announcement period. Where it
        cannot count, ANNOUNCEMENTS periods of this project's profile since our participant
        started and since the last participant found must do.
        At most MAX_SETTLE_TIME; what is still missing then is reported on stderr. With
        ``spin_time`` given, wait exactly that long instead.
        """
        start = time.monotonic()
        if self.spin_time is not None:  # spin exactly that long: the condition is never true
            spin_until(self.executor, lambda: False, self.spin_time, period=SETTLE_POLL_PERIOD)
            return
        # Participant discovery itself is not visible through ROS; what bounds it is the
        # running participants' announcement period: ANNOUNCEMENTS of them, which leaves room
        # for a loaded machine (docs/dev/limits.md). Participants found in one run arrive
        # spread out, so the same wait also follows the last participant found; on a busy
        # machine, where they arrive further apart, it is 1.5 times the longest gap between
        # two arrivals.
        period = announcement_period() * ANNOUNCEMENTS + 0.05
        all_announced = self.started + period
        participants = self.participants()
        last_found, longest_gap = self.started, 0.0
        domain_id = self.node.context.get_domain_id()
        expected = local_participants(domain_id) if self.discovery.available else None
        # No count at first can be a moment's gap (a socket whose process was ending while
        # /proc was read, with lists started together): count again while the periods run.
        recount_uncounted = expected is None and self.discovery.available
        next_count = all_announced
        next_uncounted = time.monotonic() + RECOUNT_PERIOD
        while True:
            now = time.monotonic()
            if expected is None and recount_uncounted and now >= next_uncounted:
                expected = local_participants(domain_id)
                next_uncounted = now + RECOUNT_PERIOD
            if expected is not None and heard_from_all(expected, participants):
                # Counted again: a participant made meanwhile must not stand in for one
                # that was there at the first count (both count for their process). No
                # answer this time (a process ending meanwhile): ask again next round.
                recount = local_participants(domain_id)
                if recount is not None and heard_from_all(recount, participants):
                    if not unexplained(recount, participants):
                        break
                    # Someone the count cannot see: wait the periods out, counting no more.
                    expected, recount_uncounted = None, False
                elif recount is not None:
                    expected = recount
            elif expected is not None and now >= next_count:
                # Someone counted is still unheard after our profile's periods: a participant
                # that announces less often. A plain rclpy node (Fast DDS's default, every
                # 3 s) may miss its first exchange with a newcomer and be heard only at its
                # next announcement: keep waiting for it, unless its
                # process has ended meanwhile (counted again now and then).
                recount = local_participants(domain_id)
                if recount is not None:
                    expected = still_there(expected, recount)
                next_count = now + RECOUNT_PERIOD
            if expected is None and now >= all_announced:
                break
            if now - start >= MAX_SETTLE_TIME:
                print(
                    f"warning: after {MAX_SETTLE_TIME:g} s processes were still being "
                    "discovered (a very busy machine?); the list may miss some",
                    file=sys.stderr,
                )
                break
            self.spin_once(SETTLE_POLL_PERIOD)
            found = self.participants()
            if not found <= participants:
                participants |= found
                now = time.monotonic()
                longest_gap, last_found = max(longest_gap, now - last_found), now
                all_announced = max(all_announced, now + max(period, 1.5 * longest_gap))

        def complete() -> bool:
            # One look costs a query per DDS topic (0.1 to 0.3 s with 20 nodes on a loaded
            # machine), so look only once the participants have had time to announce.
            self.discovery.take()
            self.incomplete = self.missing()
            return not self.incomplete

        remaining = max(0.0, MAX_SETTLE_TIME - (time.monotonic() - start))
        if not spin_until(self.executor, complete, remaining, period=SETTLE_POLL_PERIOD):
            print(
                f"warning: after {MAX_SETTLE_TIME:g} s discovery is still incomplete "
                f"({'; '.join(self.incomplete[:3])}); the list may miss something",
                file=sys.stderr,
            )

    def participants(self) -> set[bytes]:
        """The participants (ROS 2 processes) seen: each has a ros_discovery_info writer."""
        return {
            participant_of(bytes(endpoint.endpoint_gid))
            for endpoint in self.node.get_publishers_info_by_topic(DISCOVERY_TOPIC, no_mangle=True)
        }

    def missing(self) -> list[str]:
        """What participants announced that our graph does not hold yet ([] if nothing)."""
        if not self.discovery.available:
            return []  # no announcements to compare with: the announcement period must do
        participants = self.participants()
        own = self.node.get_name()
        missing: list[str] = []
        known_nodes = set(self.node.get_node_names_and_namespaces())
        announced: list[tuple[str, list]] = []  # (node, its reader and writer GIDs)
        for participant in sorted(participants):
            info = self.discovery.latest.get(participant)
            if info is None:
                missing.append(f"participant {participant.hex()} has not said what it holds")
                continue
            for entry in info.node_entities_info_seq:
                if entry.node_name == own:
                    continue
                name = join_node_name(entry.node_namespace, entry.node_name)
                if (entry.node_name, entry.node_namespace) not in known_nodes:
                    missing.append(f"node {name}")
                else:
                    announced.append((name, [*entry.reader_gid_seq, *entry.writer_gid_seq]))
        if missing:
            return missing  # the endpoints' turn comes after: they cost more to look at
        endpoints = self._endpoint_gids()
        for name, gids in announced:
            unseen = sum(bytes(gid.data) not in endpoints for gid in gids)
            if unseen:
                missing.append(f"{unseen} endpoint(s) of {name}")
        return missing

    def _endpoint_gids(self) -> dict[bytes, str]:
        """Every reader and writer in our graph (topics, services, ...): GID -> node name."""
        found: dict[bytes, str] = {}
        node = self.node
        for name, _types in node.get_topic_names_and_types(no_demangle=True):
            for endpoint in (
                *node.get_publishers_info_by_topic(name, no_mangle=True),
                *node.get_subscriptions_info_by_topic(name, no_mangle=True),
            ):
                if endpoint.node_name != UNKNOWN_NODE:
                    found[bytes(endpoint.endpoint_gid)] = endpoint.node_name
        return found

    def snapshot(self) -> Snapshot:
        """The graph as it is now (call settle() first for a complete one)."""
        node = self.node
        nodes = self.node_names()
        topics: dict[str, TopicInfo] = {}
        for name, types in self.topic_types().items():
            info = topics[name] = TopicInfo(types)
            for endpoints, found in (
                (info.publishers, node.get_publishers_info_by_topic(name)),
                (info.subscribers, node.get_subscriptions_info_by_topic(name)),
            ):
                for endpoint in found:
                    if endpoint.node_name.startswith("_"):  # the tools' own, or unknown yet
                        continue
                    full = join_node_name(endpoint.node_namespace, endpoint.node_name)
                    endpoints.append(Endpoint(full, endpoint.qos_profile))
        services: dict[str, ServiceInfo] = {}
        actions: dict[str, ServiceInfo] = {}
        for full in list(nodes):
            try:
                offers = self._offers(full)
            except RuntimeError:  # rclpy's NodeNameNonExistentError: it has just gone
                nodes.remove(full)
                continue
            for kind, role, offered in offers:
                table = services if kind == "services" else actions
                for offered_name, types in offered:
                    if is_hidden(offered_name):
                        continue
                    entry = table.setdefault(offered_name, ServiceInfo(list(types)))
                    getattr(entry, role).append(full)
        return Snapshot(nodes, topics, services, actions)

    def _offers(self, full_name: str) -> list[tuple[str, str, list]]:
        """A node's services and actions: ('services'|'actions', 'servers'|'clients', names)."""
        node = self.node
        namespace, name = split_node_name(full_name)
        action_servers, action_clients = self.node_actions(name, namespace)
        return [
            ("services", "servers", node.get_service_names_and_types_by_node(name, namespace)),
            ("services", "clients", node.get_client_names_and_types_by_node(name, namespace)),
            ("actions", "servers", action_servers),
            ("actions", "clients", action_clients),
        ]

    def node_actions(self, name: str, namespace: str) -> tuple[list, list]:
        """The action servers and the action clients of a node: (name, types) each."""
        from rclpy.action.graph import (
            get_action_client_names_and_types_by_node,
            get_action_server_names_and_types_by_node,
        )

        return (
            get_action_server_names_and_types_by_node(self.node, name, namespace),
            get_action_client_names_and_types_by_node(self.node, name, namespace),
        )

    def action_types(self) -> dict[str, list[str]]:
        from rclpy.action.graph import get_action_names_and_types

        return dict(get_action_names_and_types(self.node))

    def call(self, client, request, what: str):
        """Wait for the server, call it, and wait for the response; all within the timeout."""
        self.wait_for(client.service_is_ready, f"{what}: service '{client.srv_name}' not available")
        future = client.call_async(request)
        self.wait_for(future.done, f"{what}: no response from '{client.srv_name}'")
        return future.result()
