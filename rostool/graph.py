"""The ROS graph as the command-line tools see it: one hidden node, and waiting that is bounded.

Every command starts one node (its name begins with ``_`` so ``node list`` hides it, as
ros2cli hides its own) and asks the graph. DDS discovery is asynchronous: a node that
is already running shows up in a new process after a few milliseconds, or after the
running participants' next announcement (every 0.25 s with this project's Fast DDS
profile, every 3 s with Fast DDS's default). So a command never sleeps a
fixed time: it polls until what it needs appears (``wait_for``), and reports "unknown
..." only when its timeout has passed. Listing commands cannot know what they have not
seen yet; they wait until another node has shown up and the graph has been quiet for a
moment (``settle``, at most MAX_SETTLE_TIME), or exactly ``spin_time`` seconds if given:
discovery can also deliver a node's endpoints in parts seconds apart, and only a fixed
wait long enough makes a list complete.
"""

from __future__ import annotations

import contextlib
import os
import signal
import time
from collections.abc import Callable
from typing import TypeVar

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions

from ros_tutorials_common.node_main import init
from rostool.errors import ToolError

DEFAULT_TIMEOUT = 5.0  # how long a command waits for the thing it names to appear
MAX_SETTLE_TIME = 4.0  # the most a listing command waits for discovery (slow case ~3 s)
QUIET_TIME = 0.25  # a listing is complete once the graph has not changed for this long
POLL_PERIOD = 0.02

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
    process gets the CPU back after printing.
    """
    return contextlib.suppress(KeyboardInterrupt, ExternalShutdownException)


class Graph:
    """One hidden node in a fresh rclpy context, and helpers that wait on the graph."""

    def __init__(self, timeout: float = DEFAULT_TIMEOUT, spin_time: float | None = None):
        self.timeout = timeout
        self.spin_time = spin_time
        self.finished = False  # see finish()
        # SIGTERM only: Ctrl-C stays Python's KeyboardInterrupt and ROS keeps running, so
        # that `action send_goal` can still cancel its goal after it.
        init(["rostool"], signal_handler_options=SignalHandlerOptions.SIGTERM)
        # No parameter services or rosout: the tool's node should not clutter what it shows.
        self.node = Node(
            f"_rostool_{os.getpid()}", start_parameter_services=False, enable_rosout=False
        )
        self.executor = SingleThreadedExecutor()
        self.executor.add_node(self.node)

    def close(self) -> None:
        """Destroy the node and shut ROS down; a Ctrl-C meanwhile takes effect afterwards.

        Closing is short, and one interrupted half-way would leave rclpy to complain at exit.
        """
        pressed = []
        previous = signal.signal(signal.SIGINT, lambda *_: pressed.append(True))
        try:
            self.executor.shutdown()
            self.node.destroy_node()
            rclpy.try_shutdown()
        finally:
            signal.signal(signal.SIGINT, previous)
        if pressed and callable(previous):
            previous(signal.SIGINT, None)  # Python's default raises KeyboardInterrupt now

    def __enter__(self) -> Graph:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.close()

    def finish(self) -> None:
        """A one-shot command has its answer: call this just before printing it.

        From then on a Ctrl-C (the user answering the printed line, however late the
        process gets the CPU back) does not make the command "interrupted" (130): its exit
        status stays 0 (see cli.execute). The counterpart of until_stopped.
        """
        self.finished = True

    def spin_once(self, timeout: float = POLL_PERIOD) -> None:
        self.executor.spin_once(timeout_sec=timeout)

    def wait_for(self, condition: Callable[[], T], what: str, timeout: float | None = None) -> T:
        """Spin until condition() gives something truthy and return it; ToolError on timeout."""
        timeout = self.timeout if timeout is None else timeout
        deadline = time.monotonic() + timeout
        while True:
            result = condition()
            if result:
                return result
            if time.monotonic() > deadline:
                raise ToolError(f"{what} (waited {timeout:g} s)")
            self.spin_once()

    def settle(self) -> None:
        """Let discovery run before listing: until other nodes are seen and nothing changes."""
        start = time.monotonic()
        if self.spin_time is not None:
            while time.monotonic() - start < self.spin_time:
                self.spin_once()
            return
        last_change = start
        snapshot = None
        while time.monotonic() - start < MAX_SETTLE_TIME:
            current = (
                sorted(self.node.get_node_names_and_namespaces()),
                sorted(self.node.get_topic_names_and_types()),
                sorted(self.node.get_service_names_and_types()),
            )
            now = time.monotonic()
            if current != snapshot:
                snapshot, last_change = current, now
            others_seen = len(current[0]) > 1
            if others_seen and now - last_change >= QUIET_TIME:
                return
            self.spin_once()

    # What the graph holds, hidden names left out as ros2cli does.

    def node_names(self) -> list[str]:
        names = self.node.get_node_names_and_namespaces()
        return sorted(join_node_name(ns, name) for name, ns in names if not name.startswith("_"))

    def topic_types(self) -> dict[str, list[str]]:
        return {n: t for n, t in self.node.get_topic_names_and_types() if not is_hidden(n)}

    def service_types(self) -> dict[str, list[str]]:
        return {n: t for n, t in self.node.get_service_names_and_types() if not is_hidden(n)}

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

    def call(self, client, request, what: str):
        """Wait for the server, call it, and wait for the response; all within the timeout."""
        self.wait_for(client.service_is_ready, f"{what}: service '{client.srv_name}' not available")
        future = client.call_async(request)
        self.wait_for(future.done, f"{what}: no response from '{client.srv_name}'")
        return future.result()
