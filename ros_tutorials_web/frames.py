"""The web viewer's tf panel, ROS side: the tf2 frame tree as view_frames shows it and each
frame's pose in a fixed frame, for the page to draw each frame's axes.

The transforms come from tf2_ros's Buffer and TransformListener (the project's one transform
core): the tree from ``Buffer.all_frames_as_yaml()``, each pose from
``Buffer.lookup_transform(fixed, frame, Time())``. The listener exists only while a browser
tab asks for the frames, and is dropped with the last one.

Bounded, whatever is broadcast: a snapshot goes out at most ``TF_HZ`` times a second, and
less often when a large tree makes one costly (at most ``SHARE`` of the ROS thread's time);
it carries at most ``MAX_FRAMES`` frames (the page says how many there are). A frame whose
pose cannot be looked up (a loop, a frame in another tree) is sent with tf2's reason.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from rclpy.node import Node
from rclpy.time import Time

TF_HZ = 10.0  # the most snapshots a second
SHARE = 0.2  # the most of the ROS thread's time the snapshots may take
MAX_FRAMES = 200  # frames sent per snapshot (tree order: the roots and their nearest first)
MAX_NAME = 256  # characters of a fixed frame's name a tab may ask for
AUTO = ""  # a tab's fixed frame when it names none: "world" if there is one, else a root
PREFERRED_FIXED = "world"  # turtle_tf2's fixed frame, turtlesim's origin


@dataclass
class Frame:
    """One frame as tf2's all_frames_as_yaml() describes it (the fields view_frames shows)."""

    name: str
    parent: str
    broadcaster: str
    rate: float
    most_recent: float  # s; 0 for a static transform
    oldest: float
    buffer_length: float


DEFAULTS = {"broadcaster": "", "rate": 0.0, "most_recent": 0.0, "oldest": 0.0, "buffer_length": 0.0}


FIELDS = {  # tf2's YAML key -> Frame's field
    "parent": "parent",
    "broadcaster": "broadcaster",
    "rate": "rate",
    "most_recent_transform": "most_recent",
    "oldest_transform": "oldest",
    "buffer_length": "buffer_length",
}


def parse_frames(text: str) -> dict[str, Frame]:
    """The frames of tf2's YAML listing (all_frames_as_yaml), by name.

    Read line by line in the layout tf2 writes, not by a YAML parser: tf2 writes a frame's
    name unquoted, so a name with ``: `` or ``#`` in it is not YAML, and the frames around it
    must still show (and 10,000 frames are read in a blink)."""
    frames: dict[str, Frame] = {}
    fields: dict[str, Any] = {}
    name: str | None = None

    def keep() -> None:
        if name is not None and "parent" in fields:
            frames[name] = Frame(name=name, **{**DEFAULTS, **fields})

    for line in text.splitlines():
        if not line.startswith("  "):  # "NAME: ": a frame's first line
            keep()
            name, fields = (line[:-2] if line.endswith(": ") else line.rstrip(":")), {}
            continue
        key, _, value = line.strip().partition(": ")
        if key in ("parent", "broadcaster"):
            fields[FIELDS[key]] = value[1:-1] if value[:1] == value[-1:] == "'" else value
        elif key in FIELDS:
            try:
                fields[FIELDS[key]] = float(value)
            except ValueError:
                pass
    keep()
    return frames


def tree_order(frames: dict[str, Frame]) -> tuple[dict[str, int], list[str], set[str]]:
    """(each root with how many frames hang below it, every frame in depth-first order from
    the roots, the frames in a loop).

    A root is a parent with no parent of its own. Frames that no root reaches hang in a
    loop (a -> b -> a): they come last, so the page can show them too."""
    children: dict[str, list[str]] = {}
    for frame in frames.values():
        children.setdefault(frame.parent, []).append(frame.name)
    roots = {parent: 0 for parent in sorted(children) if parent not in frames}
    order: list[str] = []
    seen: set[str] = set()
    for root in roots:
        before = len(order)
        stack = [root]
        while stack:  # iterative: a chain of 10,000 frames is no recursion limit
            name = stack.pop()
            if name in seen:
                continue
            seen.add(name)
            order.append(name)
            stack.extend(sorted(children.get(name, ()), reverse=True))
        roots[root] = len(order) - before - 1
    looped = sorted(set(frames) - seen)
    return roots, order + looped, set(looped)


def finite(value: float, digits: int = 6) -> float | None:
    """A number for JSON (which has no NaN or infinity): None when it is not finite."""
    return round(value, digits) if math.isfinite(value) else None


def pose(transform: Any) -> dict[str, Any]:
    """A geometry_msgs/TransformStamped as the page draws it: the frame's origin, its
    rotation, and its x and y axes (unit vectors) seen from above (the fixed frame's xy)."""
    t, q = transform.transform.translation, transform.transform.rotation
    x, y, z, w = q.x, q.y, q.z, q.w
    x_axis = (1 - 2 * (y * y + z * z), 2 * (x * y + w * z))  # R times (1, 0, 0), its x and y
    y_axis = (2 * (x * y - w * z), 1 - 2 * (x * x + z * z))  # R times (0, 1, 0)
    return {
        "xyz": [finite(t.x), finite(t.y), finite(t.z)],
        "q": [finite(x), finite(y), finite(z), finite(w)],
        "yaw": finite(math.atan2(x_axis[1], x_axis[0])),
        "x_axis": [finite(v) for v in x_axis],
        "y_axis": [finite(v) for v in y_axis],
    }


def default_fixed(roots: dict[str, int], frames: dict[str, Frame]) -> str | None:
    """The fixed frame of a tab that names none: world, else the root with most frames."""
    if PREFERRED_FIXED in roots or PREFERRED_FIXED in frames:
        return PREFERRED_FIXED
    return min(roots, key=lambda root: (-roots[root], root), default=None)


def snapshots(buffer: Any, wanted: list[str], now: float) -> dict[str, dict[str, Any]]:
    """The tf message for the tabs of each fixed frame wanted (AUTO: the viewer chooses), at
    ROS time ``now`` (s): the tree, each frame's rate and age, and its pose."""
    frames = parse_frames(buffer.all_frames_as_yaml())
    roots, order, looped = tree_order(frames)
    shown = order[:MAX_FRAMES]
    messages = {}
    for fixed in wanted:
        used = fixed or default_fixed(roots, frames)
        messages[fixed] = {
            "type": "tf",
            "fixed": used,
            "asked": fixed,
            "stamp": finite(now, 3),
            "total": len(order),
            "capped": len(order) > len(shown),
            "frames": entries(buffer, frames, shown, looped, used, now),
        }
    return messages


def entries(
    buffer: Any,
    frames: dict[str, Frame],
    shown: list[str],
    looped: set[str],
    fixed: str | None,
    now: float,
) -> list[dict[str, Any]]:
    """What the page shows of each frame: view_frames' figures and the pose in ``fixed``."""
    from tf2_ros import TransformException

    found = []
    for name in shown:
        entry: dict[str, Any] = {"name": name, "parent": None, "loop": name in looped}
        frame = frames.get(name)
        if frame is not None:
            static = frame.most_recent == 0.0  # a static transform holds for all time
            entry.update(
                parent=frame.parent,
                broadcaster=frame.broadcaster,
                rate=finite(frame.rate, 3),
                static=static,
                most_recent=finite(frame.most_recent, 3),
                oldest=finite(frame.oldest, 3),
                buffer_length=finite(frame.buffer_length, 3),
                age=None if static else finite(now - frame.most_recent, 3),
            )
        if fixed is not None:
            try:
                entry["pose"] = pose(buffer.lookup_transform(fixed, name, Time()))
            except TransformException as error:
                entry["pose"] = None
                entry["error"] = (str(error).splitlines() or [type(error).__name__])[0][:300]
        found.append(entry)
    return found


class FrameWatch:
    """The tf listener of the viewer's node, while tabs want the frames, and its snapshots.

    Runs on the ROS thread only (the Watcher's requests and timers); ``on_tf(fixed, payload)``
    must only hand over."""

    def __init__(self, node: Node, on_tf: Callable[[str, str], None]) -> None:
        self.node = node
        self._on_tf = on_tf
        self.wanted: dict[str, int] = {}  # fixed frame (AUTO: the viewer's choice) -> tabs
        self.buffer: Any = None
        self._listener: Any = None
        self._timer: Any = None
        self._next = 0.0  # monotonic time of the next snapshot
        self._failed = False  # a snapshot failed: said once

    def want(self, fixed: str, delta: int) -> None:
        """One more (delta 1) or one fewer (-1) tab shows the frames in ``fixed``."""
        count = self.wanted.get(fixed, 0) + delta
        if count > 0:
            self.wanted[fixed] = count
        else:
            self.wanted.pop(fixed, None)
        if self.wanted and self._listener is None:
            self._start()
        elif not self.wanted and self._listener is not None:
            self._stop()
        self._next = 0.0  # a tab that just asked gets the frames at once

    def _start(self) -> None:
        from tf2_ros import Buffer, TransformListener

        self.buffer = Buffer()
        self._listener = TransformListener(self.buffer, self.node)
        self._timer = self.node.create_timer(1 / TF_HZ, self.tick)

    def _stop(self) -> None:
        self._listener.unregister()
        self.node.destroy_timer(self._timer)
        self._listener = self._timer = self.buffer = None

    def tick(self) -> None:
        """A snapshot per fixed frame wanted, unless the last ones were too recent."""
        started = time.monotonic()
        if not self.wanted or started < self._next:
            return
        now = self.node.get_clock().now().nanoseconds / 1e9
        try:
            for fixed, message in snapshots(self.buffer, list(self.wanted), now).items():
                self._on_tf(fixed, json.dumps(message))
        except Exception as error:  # a callback must not end the viewer
            if not self._failed:
                self._failed = True
                self.node.get_logger().warning(f"Cannot show the tf frames: {error}")
        cost = time.monotonic() - started
        # Slack: the timer's own period must not make every second snapshot skipped.
        self._next = started + max(1 / TF_HZ, cost / SHARE) - 0.5 / TF_HZ
