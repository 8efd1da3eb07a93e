"""rviz2's ROS side: one rclpy node (``rviz2``) that subscribes to what its displays show, keeps
tf2's frames, and hands the 3D view's page what it draws (encode.py, robot_model.py).

It only subscribes: it publishes nothing and changes nothing in the graph. Each display keeps
only its newest message (a newer one replaces it before it is drawn), except Marker and
MarkerArray, which keep the markers they have been told to add (at most ``encode.MAX_MARKERS``,
each until deleted or its lifetime ends). A timer (``RATE`` a second, while a page is open)
turns what changed into payloads and hands them over with ``handoff(stream, payload)``, which
must only hand over (the web server queues nothing either: a tab gets the newest payload of
each stream).

Streams: ``config`` (the fixed frame, the displays with each one's status, the topics a
display could be added for), ``tf`` (every frame's parent and pose in the fixed frame),
``display:N`` (display N's data: JSON text, or a binary frame with bulk data).

Runs on the ROS thread only; the web server asks for changes with ``request(callable)``.
"""

from __future__ import annotations

import json
import math
import struct
import time
from collections.abc import Callable
from typing import Any

from rclpy.node import Node
from rclpy.qos import (
    DurabilityPolicy,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_sensor_data,
)
from rclpy.time import Time

from ros_tutorials_common.ros import ThreadRequests
from rviz2 import encode, robot_model
from rviz2.config import BY_TYPE, Config, Display, display

RATE = 30.0  # payloads a second, at most, per stream
GRAPH_PERIOD = 1.0  # s between looks at the topics (for displays added by topic)
MAX_FRAMES = 500  # tf frames sent
PREFERRED_FIXED = ("map", "world", "odom")  # the fixed frame when none is named
SENSORS = ("LaserScan", "PointCloud2", "Image")  # subscribed best effort: any publisher fits
LATCHED = ("RobotModel", "Map")  # transient local, as rviz2 subscribes to them
MARKER_ADD, MARKER_DELETE, MARKER_DELETEALL = 0, 2, 3

Handoff = Callable[[str, "str | bytes"], None]


def binary_frame(header: dict[str, Any], blob: bytes) -> bytes:
    """A binary WebSocket frame: the JSON header's length (4 bytes, big-endian), the header,
    then the bulk data."""
    encoded = json.dumps(header).encode()
    return struct.pack("!I", len(encoded)) + encoded + blob


def qos_of(kind: str) -> QoSProfile:
    if kind in SENSORS:
        return qos_profile_sensor_data
    if kind in LATCHED:
        return QoSProfile(
            depth=1,
            durability=DurabilityPolicy.TRANSIENT_LOCAL,
            reliability=ReliabilityPolicy.RELIABLE,
        )
    return QoSProfile(depth=100 if kind in ("Marker", "MarkerArray") else 10)


class DisplayState:
    """One display: its subscription, its newest message (or its markers) and its status."""

    def __init__(self, number: int, display: Display) -> None:
        self.number = number
        self.display = display
        self.subscription: Any = None
        self.newest: Any = None
        self.changed = False
        self.count = 0
        self.status = "ok" if display.type_name is None else "waiting for messages"
        self.markers: dict[tuple[str, int], tuple[dict[str, Any], float]] = {}
        self.model: robot_model.RobotModel | None = None

    def as_dict(self) -> dict[str, Any]:
        entry = self.display.as_dict(self.number)
        entry.update(status=self.status, count=self.count)
        return entry


class Scene(Node):
    def __init__(
        self,
        config: Config,
        handoff: Handoff,
        package_share: Callable[[str], Any],
        by_topic: bool = False,
        context: Any = None,
    ) -> None:
        super().__init__("rviz2", context=context)
        from tf2_ros import Buffer, TransformListener

        self.handoff = handoff
        self.package_share = package_share
        self.by_topic = by_topic  # add a display for every topic of a type the view draws
        self.fixed_asked = config.fixed_frame  # None: the view chooses
        self.fixed = config.fixed_frame or PREFERRED_FIXED[0]
        self.lacking = list(config.lacking)
        self.view = dict(config.view)
        self.displays: list[DisplayState] = []
        self.topics: dict[str, str] = {}  # drawable topics in the graph -> type
        self.buffer = Buffer()
        self.listener = TransformListener(self.buffer, self, spin_thread=False)
        self.request = ThreadRequests(self)  # from the web server's thread
        self._config_changed = True
        self._last_tf = ""
        self.viewers = 0  # pages open (set_viewers)
        for item in config.displays:
            self.add(item)
        self.create_timer(1 / RATE, self.tick)
        self.create_timer(GRAPH_PERIOD, self.look_at_graph)
        self.look_at_graph()

    # --- the displays
    def add(self, item: Display) -> DisplayState:
        state = DisplayState(len(self.displays), item)
        self.displays.append(state)
        if item.enabled:
            self.subscribe(state)
        self._config_changed = True
        return state

    def add_for_topic(self, topic: str) -> None:
        """A display for a topic of the graph (the page's "add by topic")."""
        kind = BY_TYPE.get(self.topics.get(topic, ""))
        if kind is None or any(s.display.topic == topic for s in self.displays):
            return
        self.add(display(kind, topic))  # named after its kind, as rviz names it

    def set_enabled(self, number: int, enabled: bool) -> None:
        if not 0 <= number < len(self.displays):
            return
        state = self.displays[number]
        if state.display.enabled == enabled:
            return
        state.display.enabled = enabled
        if enabled:
            self.subscribe(state)
        else:
            self.unsubscribe(state)
        self._config_changed = True

    def set_fixed(self, frame: str) -> None:
        self.fixed_asked = frame or None
        self._config_changed = True

    def subscribe(self, state: DisplayState) -> None:
        item = state.display
        if item.type_name is None or item.topic is None or state.subscription is not None:
            return
        from ros2cmd.typenames import load_type

        try:
            message_class = load_type(item.type_name)
        except Exception as error:
            state.status = f"error: cannot load {item.type_name}: {error}"
            return

        def take(msg: Any) -> None:
            state.count += 1
            if item.kind == "Marker":
                self.take_markers(state, [msg])
            elif item.kind == "MarkerArray":
                self.take_markers(state, msg.markers)
            else:
                state.newest = msg
            state.changed = True

        try:
            state.subscription = self.create_subscription(
                message_class, item.topic, take, qos_of(item.kind)
            )
        except Exception as error:  # a topic name rcl refuses
            state.status = f"error: cannot subscribe to {item.topic!r}: {error}"
            return
        state.status = "waiting for messages"

    def unsubscribe(self, state: DisplayState) -> None:
        if state.subscription is not None:
            self.destroy_subscription(state.subscription)
            state.subscription = None
        state.newest, state.model = None, None
        state.markers.clear()
        state.status = "disabled"
        self.handoff(f"display:{state.number}", json.dumps({"id": state.number, "clear": True}))

    def take_markers(self, state: DisplayState, markers: list[Any]) -> None:
        now = time.monotonic()
        for msg in markers:
            if msg.action == MARKER_DELETEALL:
                state.markers.clear()
            elif msg.action == MARKER_DELETE:
                state.markers.pop((msg.ns, msg.id), None)
            elif msg.action in (MARKER_ADD, 1):
                entry = encode.marker(msg)
                expires = now + entry["lifetime"] if entry["lifetime"] > 0 else math.inf
                key = (msg.ns, msg.id)
                if key in state.markers or len(state.markers) < encode.MAX_MARKERS:
                    state.markers[key] = (entry, expires)

    # --- the graph: the topics a display could be added for
    def look_at_graph(self) -> None:
        topics = {}
        for name, types in self.get_topic_names_and_types():
            kind = next((BY_TYPE[t] for t in types if t in BY_TYPE), None)
            if kind is not None:
                topics[name] = next(t for t in types if t in BY_TYPE)
        if topics != self.topics:
            self.topics = topics
            self._config_changed = True
        if self.by_topic:
            for name in sorted(topics):
                self.add_for_topic(name)

    # --- the timer: what changed, as payloads
    def set_viewers(self, count: int) -> None:
        """How many pages are open: with none, the timer encodes nothing (what changed
        meanwhile is sent, newest first, when a page opens)."""
        self.viewers = count

    def tick(self) -> None:
        if not self.viewers:  # only the robot model, read at once: a bad URDF is said now
            for state in self.displays:
                if state.display.kind == "RobotModel" and state.changed and state.display.enabled:
                    state.changed = False
                    self.send_display(state)
            return
        parents = self.parents()
        self.choose_fixed(parents)
        if self._config_changed:  # before the displays: the page makes a display from it
            self._config_changed = False
            self.handoff("config", json.dumps(self.config_payload()))
        self.send_tf(parents)
        now = time.monotonic()
        for state in self.displays:
            if state.markers and any(exp <= now for _, exp in state.markers.values()):
                for key in [k for k, (_, exp) in state.markers.items() if exp <= now]:
                    del state.markers[key]
                state.changed = True
            if state.changed and state.display.enabled:
                state.changed = False
                self.send_display(state)
        if self._config_changed:
            self._config_changed = False
            self.handoff("config", json.dumps(self.config_payload()))

    def choose_fixed(self, parents: dict[str, str]) -> None:
        if self.fixed_asked:
            fixed = self.fixed_asked
        else:
            frames = set(parents) | set(parents.values())
            fixed = next((f for f in PREFERRED_FIXED if f in frames), None)
            roots = sorted(frames - set(parents))
            if fixed is None and roots:  # the root with the most frames below it
                fixed = max(
                    roots, key=lambda root: sum(self.root(f, parents) == root for f in frames)
                )
            fixed = fixed or PREFERRED_FIXED[0]
        if fixed != self.fixed:
            self.fixed = fixed
            self._config_changed = True

    @staticmethod
    def root(frame: str, parents: dict[str, str]) -> str:
        steps = 0
        while frame in parents and steps < MAX_FRAMES:
            frame, steps = parents[frame], steps + 1
        return frame

    def parents(self) -> dict[str, str]:
        from ros_tutorials_web.frames import parse_frames

        return {f.name: f.parent for f in parse_frames(self.buffer.all_frames_as_yaml()).values()}

    def config_payload(self) -> dict[str, Any]:
        return {
            "type": "config",
            "fixed": self.fixed,
            "fixed_asked": self.fixed_asked,
            "displays": [state.as_dict() for state in self.displays],
            "lacking": self.lacking,
            "view": self.view,
            "topics": self.topics,
        }

    def send_tf(self, parents: dict[str, str]) -> None:
        from tf2_ros import TransformException

        names = sorted(set(parents) | set(parents.values()))[:MAX_FRAMES]
        frames = []
        for name in names:
            entry: dict[str, Any] = {"name": name, "parent": parents.get(name)}
            try:
                t = self.buffer.lookup_transform(self.fixed, name, Time())
                tr, q = t.transform.translation, t.transform.rotation
                entry["p"] = [tr.x, tr.y, tr.z]
                entry["q"] = [q.x, q.y, q.z, q.w]
            except TransformException as error:
                entry["error"] = (str(error).splitlines() or ["no transform"])[0][:200]
            frames.append(entry)
        payload = json.dumps({"type": "tf", "fixed": self.fixed, "frames": frames})
        if payload != self._last_tf:
            self._last_tf = payload
            self.handoff("tf", payload)

    def send_display(self, state: DisplayState) -> None:
        kind = state.display.kind
        head: dict[str, Any] = {"type": "display", "id": state.number, "kind": kind}
        status = "ok"
        try:
            if kind in ("Marker", "MarkerArray"):
                head["markers"] = [entry for entry, _ in state.markers.values()]
                payload: str | bytes = json.dumps(head)
            elif kind == "RobotModel":
                payload = self.robot_payload(state, head)
            elif state.newest is not None:
                header, blob = encode.ENCODERS[kind](state.newest)
                head.update(header)
                payload = binary_frame(head, blob) if blob else json.dumps(head)
            else:
                return
        except Exception as error:  # a message its type allows but the view cannot draw
            status = "error: " + ((str(error).splitlines() or [type(error).__name__])[0][:300])
            payload = json.dumps({"type": "display", "id": state.number, "clear": True})
        state.newest = None if kind != "RobotModel" else state.newest
        if status != state.status:
            state.status = status
            self._config_changed = True
            if status != "ok":
                self.get_logger().warning(f"{state.display.name}: {status}")
        self.handoff(f"display:{state.number}", payload)

    def robot_payload(self, state: DisplayState, head: dict[str, Any]) -> str:
        if state.newest is None:
            raise ValueError("no robot description yet")
        state.model = robot_model.parse(state.newest.data, self.package_share)
        head.update(state.model.as_dict())
        for problem in state.model.problems:
            self.get_logger().warning(f"{state.display.name}: {problem}")
        return json.dumps(head)

    def mesh_file(self, number: int, index: int) -> Any:
        """The mesh file the current robot model of display ``number`` names at ``index``
        (None if it names none): the only files the page may fetch."""
        if not 0 <= number < len(self.displays):
            return None
        model = self.displays[number].model
        if model is None or not 0 <= index < len(model.meshes):
            return None
        return model.meshes[index]
