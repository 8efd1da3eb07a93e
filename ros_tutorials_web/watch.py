"""The web viewer's ROS side: one ordinary rclpy node, spun in a thread of its own, that
watches the graph, /rosout, the picture topics, the topics the browsers ask for and, while a
browser shows them, the tf2 frames (frames.py).

Its callbacks never queue: each subscription keeps only its newest message, serialized (a
``Feed``), and wakes the web server's event loop once (``wake``, which the server makes
with call_soon_threadsafe) until the loop has taken it. A 1 kHz topic or a stream of 10 MB
frames thus costs the viewer one copy at a time, and the publishers are never held up.

Subscriptions are made and destroyed on the ROS thread only: the event loop asks for changes
with ``Watcher.request()``, which a guard condition hands to the executor.
"""

from __future__ import annotations

import threading
import time
from collections import deque
from collections.abc import Callable
from typing import Any

from rcl_interfaces.msg import Log
from rclpy.node import Node
from rclpy.qos import QoSProfile

from ros2cmd.console import LEVEL_NAMES, ROSOUT_QOS
from ros2cmd.graph import Graph, Snapshot
from ros2cmd.graph_view.model import model_from_snapshot
from ros2cmd.qos import qos_for
from ros2cmd.typenames import load_type
from ros_tutorials_common.drawing.layout import layout, monospace_measure
from ros_tutorials_common.drawing.render import to_svg
from ros_tutorials_common.ros import ThreadRequests
from ros_tutorials_web.frames import FrameWatch

IMAGE_TYPE = "sensor_msgs/msg/CompressedImage"
GRAPH_PERIOD = 1.0  # s between looks at the graph (nodes and topics coming and going)
LOG_KEEP = 1000  # /rosout entries kept for a browser that opens the page later
TEXT_LIMIT = 4000  # characters of one log message passed on


TOPIC_DEPTH = 10  # messages of a watched topic its subscription holds for the executor
HISTORY_BYTES = 4 * 1024 * 1024  # a topic's messages kept between two takes, for a plot


class Feed:
    """The newest message of one subscription, serialized: a newer one replaces it. Beside
    it, every message since the last take with the time it came (``take_history``: a plot
    draws them all), at most HISTORY_BYTES of them: the oldest go first."""

    def __init__(self, topic: str, type_name: str, wake: Callable[[Feed], None]) -> None:
        self.topic = topic
        self.type_name = type_name
        self.message_class = load_type(type_name)
        self.count = 0  # messages received
        self.subscription: Any = None
        self.publisher_kinds: set = set()  # the publishers' QoS when subscribed
        self._wake = wake
        self._lock = threading.Lock()
        self._data: bytes | None = None
        self._history: deque[tuple[float, bytes]] = deque()
        self._history_bytes = 0

    def put(self, data: bytes) -> None:
        """The subscription's callback (ROS thread)."""
        came = time.time()
        with self._lock:
            waiting = self._data is not None  # the event loop has been woken already
            self._data = data
            self.count += 1
            self._history.append((came, data))
            self._history_bytes += len(data)
            while self._history_bytes > HISTORY_BYTES and len(self._history) > 1:
                self._history_bytes -= len(self._history.popleft()[1])
        if not waiting:
            self._wake(self)

    def take_history(self) -> list[tuple[float, bytes]]:
        """Every message since the last take_history, with the time it came (event loop)."""
        with self._lock:
            history = list(self._history)
            self._history.clear()
            self._history_bytes = 0
        return history

    def take(self) -> bytes | None:
        """The newest message since the last take, or None (event loop)."""
        with self._lock:
            data, self._data = self._data, None
        return data


class LogFeed:
    """/rosout entries as plain data, the newest LOG_KEEP of them until taken."""

    def __init__(self, wake: Callable[[LogFeed], None]) -> None:
        self._wake = wake
        self._lock = threading.Lock()
        self._entries: deque[dict] = deque(maxlen=LOG_KEEP)

    def put(self, msg: Log) -> None:
        entry = {
            "time": msg.stamp.sec + msg.stamp.nanosec / 1e9,
            "level": LEVEL_NAMES.get(msg.level, str(msg.level)),
            "node": msg.name,
            "msg": msg.msg[:TEXT_LIMIT],
        }
        with self._lock:
            waiting = bool(self._entries)
            self._entries.append(entry)
        if not waiting:
            self._wake(self)

    def take(self) -> list[dict]:
        with self._lock:
            entries = list(self._entries)
            self._entries.clear()
        return entries


class NodeGraph(Graph):
    """The graph snapshot every tool reads (ros2cmd.graph), as seen from the viewer's node
    (Graph's own __init__ would start a hidden node in a context of its own)."""

    def __init__(self, node: Node) -> None:  # only what snapshot() reads
        self.node = node


class Watcher(Node):
    """The viewer's node. ``on_graph``, ``on_feed``, ``on_log`` and ``on_tf`` are called on
    the ROS thread and must only hand over (call_soon_threadsafe)."""

    def __init__(
        self,
        on_graph: Callable[[str, dict[str, list[str]], list[str]], None],
        on_feed: Callable[[Feed], None],
        on_log: Callable[[LogFeed], None],
        on_tf: Callable[[str, str], None],
        name: str = "web_viewer",
    ) -> None:
        super().__init__(name)
        self._on_graph = on_graph
        self._on_feed = on_feed
        self._graph = NodeGraph(self)
        self._shown: tuple | None = None  # the graph last drawn
        # request(change): change() run on the ROS thread (from any thread), then the graph
        self.request = ThreadRequests(self, after=lambda: self.look(graph=False))
        self.viewers = 0  # browsers connected: picture topics are subscribed only then
        self.wanted: dict[str, int] = {}  # topic -> how many browsers watch it
        self.images: dict[str, Feed] = {}
        self.topics: dict[str, Feed] = {}
        self.log = LogFeed(on_log)
        self.frames = FrameWatch(self, on_tf)
        self.create_subscription(Log, "/rosout", self.log.put, ROSOUT_QOS)
        self.create_timer(GRAPH_PERIOD, self.look)

    # --- asked for by the event loop -------------------------------------------------------

    def set_viewers(self, count: int) -> None:
        self.viewers = count

    def watch(self, topic: str, delta: int) -> None:
        """One more (delta 1) or one fewer (-1) browser watches topic."""
        count = self.wanted.get(topic, 0) + delta
        if count > 0:
            self.wanted[topic] = count
        else:
            self.wanted.pop(topic, None)

    # --- the graph, and the subscriptions that follow it -----------------------------------

    def look(self, graph: bool = True) -> None:
        """Subscribe to what is wanted and there, unsubscribe from the rest; draw the graph."""
        types = dict(self.get_topic_names_and_types())
        images = {name for name, kinds in types.items() if IMAGE_TYPE in kinds and self.viewers > 0}
        self._follow(self.images, images, types, lambda name: IMAGE_TYPE)
        self._follow(self.topics, set(self.wanted), types, lambda name: types[name][0])
        if graph:
            pictures = sorted(name for name, kinds in types.items() if IMAGE_TYPE in kinds)
            self._draw(self._graph.snapshot(), pictures)

    def _follow(
        self,
        feeds: dict[str, Feed],
        wanted: set[str],
        types: dict[str, list[str]],
        type_of: Callable[[str], str],
    ) -> None:
        for name in list(feeds):
            feed = feeds[name]
            kinds = self._publisher_kinds(name)
            gone = name not in wanted or feed.type_name not in types.get(name, [])
            if gone or (kinds and kinds != feed.publisher_kinds):  # QoS changed: again
                self.destroy_subscription(feed.subscription)
                del feeds[name]
        for name in wanted - set(feeds):
            if name not in types:
                continue  # not there (yet): looked for again at the next look
            try:
                feed = Feed(name, type_of(name), self._on_feed)
            except Exception:  # its Python class is not installed here: nothing to show
                continue
            feed.publisher_kinds = self._publisher_kinds(name)
            qos: QoSProfile = qos_for(feed.publisher_kinds)
            # Pictures: the newest only; a topic: a few, so a plot misses none of a fast one.
            qos.depth = 1 if feed.type_name == IMAGE_TYPE else TOPIC_DEPTH
            feed.subscription = self.create_subscription(
                feed.message_class, name, feed.put, qos, raw=True
            )
            feeds[name] = feed

    def _publisher_kinds(self, topic: str) -> set:
        return {
            (p.qos_profile.durability, p.qos_profile.reliability)
            for p in self.get_publishers_info_by_topic(topic)
        }

    def _draw(self, snapshot: Snapshot, pictures: list[str]) -> None:
        """The graph picture, the visible topics and the picture topics (hidden ones too:
        turtlesim's canvas is), passed on when one of them changed."""
        own = self.get_fully_qualified_name()
        snapshot.nodes = [name for name in snapshot.nodes if name != own]
        for info in snapshot.topics.values():  # the viewer's own subscriptions: not shown
            info.subscribers = [e for e in info.subscribers if e.node != own]
            info.publishers = [e for e in info.publishers if e.node != own]
        model = model_from_snapshot(snapshot)
        topics = {name: info.types for name, info in sorted(snapshot.topics.items())}
        key = (sorted(model.vertices), model.edges, topics, pictures)
        if key == self._shown:
            return
        self._shown = key
        self._on_graph(to_svg(layout(model, monospace_measure())), topics, pictures)
