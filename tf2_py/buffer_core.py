"""tf2's BufferCore: a tree of frames, each with its own time cache, and the lookups through it.

The method names and arguments are tf2_py's (the binding tf2_ros.Buffer inherits from):
``set_transform``, ``set_transform_static``, ``lookup_transform_core``,
``lookup_transform_full_core``, ``can_transform_core`` (-> (bool, message)),
``can_transform_full_core``, ``get_latest_common_time``, ``all_frames_as_yaml``,
``all_frames_as_string``, ``clear``, ``_frameExists``, ``_getFrameStrings``.

A lookup walks from the source frame up to the root, then from the target frame up until it
meets that path (tf2's walkToTopParent), composing the transforms on each side; time 0 means
the latest time all frames on the way have data for (tf2's latest common time). The messages
of errors and warnings are tf2's, word for word. Bad data (NaN, an unnormalised quaternion, a
frame that is its own parent, data older than the cache) is refused with tf2's error line,
never an exception: a listener's callback goes on. Unlike tf2, each such line is printed once
per frame and kind every 2.5 s (tf2's own interval for bad frame ids), so a fast broadcaster of
bad data does not flood the terminal.

(About 620 lines: the walk, the latest common time, the lookups and the frames' listings share
one frame table and its lock; split, each part would reach into the others' state.)
"""

from __future__ import annotations

import math
import threading
import time as wall
from typing import Any

from builtin_interfaces.msg import Time as TimeMessage
from geometry_msgs.msg import TransformStamped
from rclpy.time import Time

from ros_tutorials_common.quaternion import multiply, rotate
from ros_tutorials_common.ros.node_main import UNNAMED_LOGGER
from tf2_py.exceptions import (
    ConnectivityException,
    InvalidArgumentException,
    LookupException,
    TransformException,
)
from tf2_py.time_cache import (
    IDENTITY,
    NANOSECONDS,
    ZERO,
    CacheMiss,
    Entry,
    Quaternion,
    StaticCache,
    TimeCache,
    Vector,
    display_time,
    inverse,
)

# A transform as _parsed gives it: parent, child, stamp (ns), translation, rotation.
_Parsed = tuple[str, str, int, Vector, Quaternion]
DEFAULT_CACHE_TIME = 10 * NANOSECONDS  # tf2::BUFFER_CORE_DEFAULT_CACHE_TIME
MAX_GRAPH_DEPTH = 1000  # a walk longer than this is a loop
QUATERNION_NORMALIZATION_TOLERANCE = 10e-3
WARNING_INTERVAL = 2.5  # seconds between two lines of one warning for one frame
NO_PARENT = "NO_PARENT"
# rosidl_generator_py keeps each field of a message in a slot named after it with a "_" before.
_SLOTTED = "_header" in getattr(TransformStamped, "__slots__", ())


def to_nanoseconds(value: Any, what: str = "time") -> int:
    """An rclpy Time or Duration (``nanoseconds``) or a message's (``sec``, ``nanosec``)."""
    if hasattr(value, "sec") and hasattr(value, "nanosec"):
        return int(value.sec) * NANOSECONDS + int(value.nanosec)
    if hasattr(value, "nanoseconds"):
        return int(value.nanoseconds)
    raise TypeError(f"{what} must have sec and nanosec, or nanoseconds.")


def _stamp(nanoseconds: int) -> TimeMessage:
    seconds, rest = divmod(nanoseconds, NANOSECONDS)
    return TimeMessage(sec=seconds, nanosec=rest)


def _loop_message(frames: str) -> str:
    return f"The tf tree is invalid because it contains a loop.\n{frames}\n"


class BufferCore:
    """The frames and their caches. ``cache_time``: how long each frame keeps its data (an
    rclpy Duration; tf2's default 10 s). Safe to use from several threads."""

    def __init__(self, cache_time: Any = None) -> None:
        self.cache_time = (
            DEFAULT_CACHE_TIME if cache_time is None else to_nanoseconds(cache_time, "duration")
        )
        self._lock = threading.RLock()
        self._numbers: dict[str, int] = {NO_PARENT: 0}
        self._names: list[str] = [NO_PARENT]
        self._caches: list[TimeCache | StaticCache | None] = [None]
        self._authority: dict[int, str] = {}
        self._warned: dict[tuple[str, str], float] = {}

    # -- adding data ---------------------------------------------------------------------------

    def set_transform(self, transform: Any, authority: str) -> None:
        """Add one geometry_msgs TransformStamped; bad data is refused with tf2's error line
        (returns None either way, as tf2_py)."""
        self._set(transform, authority, False)

    def set_transform_static(self, transform: Any, authority: str) -> None:
        self._set(transform, authority, True)

    def set_transforms(self, transforms: Any, authority: str, is_static: bool = False) -> None:
        """Add every TransformStamped of a TFMessage's ``transforms``, under one lock (a
        listener's callback: one message of many transforms)."""
        parse, store = self._parsed, self._store
        with self._lock:
            for transform in transforms:
                parsed = parse(transform, authority)
                if parsed is not None:
                    store(parsed, authority, is_static)

    def _set(self, message: Any, authority: str, is_static: bool) -> bool:
        parsed = self._parsed(message, authority)
        if parsed is None:
            return False
        with self._lock:
            return self._store(parsed, authority, is_static)

    def _parsed(self, message: Any, authority: str) -> _Parsed | None:
        """(parent, child, stamp, translation, normalised rotation) of a TransformStamped;
        None, with tf2's line, for data tf2 refuses."""
        if type(message) is TransformStamped and _SLOTTED:
            # rosidl's own class: its setters made every field's type, so its fields are read
            # from their slots (a property per field costs half the listener's callback).
            header, transform = message._header, message._transform
            stamp, t, r = header._stamp, transform._translation, transform._rotation
            stamp = stamp._sec * NANOSECONDS + stamp._nanosec
            tx, ty, tz, rx, ry, rz, rw = t._x, t._y, t._z, r._x, r._y, r._z, r._w
            parent, child = header._frame_id, message._child_frame_id
        else:
            try:
                header = message.header
                transform = message.transform
                t, r = transform.translation, transform.rotation
                stamp = to_nanoseconds(header.stamp)
                tx, ty, tz = float(t.x), float(t.y), float(t.z)
                rx, ry, rz, rw = float(r.x), float(r.y), float(r.z), float(r.w)
                parent = header.frame_id
                child = message.child_frame_id
            except AttributeError:
                raise TypeError(
                    "transform must be a TransformStamped (header, child_frame_id, transform)"
                ) from None
        if parent[:1] == "/":
            parent = parent[1:]
        if child[:1] == "/":
            child = child[1:]
        norm2 = rx * rx + ry * ry + rz * rz + rw * rw
        total = tx + ty + tz + norm2
        if (
            child == parent
            or not child
            or not parent
            or total != total  # a NaN among them (or infinities that cancel: looked at below)
            or not abs(norm2 - 1.0) < QUATERNION_NORMALIZATION_TOLERANCE
        ) and not self._acceptable(parent, child, (tx, ty, tz), (rx, ry, rz, rw), norm2, authority):
            return None
        norm = math.sqrt(norm2)
        return parent, child, stamp, (tx, ty, tz), (rx / norm, ry / norm, rz / norm, rw / norm)

    def _store(self, parsed: _Parsed, authority: str, is_static: bool) -> bool:
        """Keep a parsed transform in its frame's cache (the lock held)."""
        parent, child, stamp, translation, rotation = parsed
        numbers = self._numbers
        number = numbers.get(child) or self._number(child, insert=True)
        cache = self._caches[number]
        if cache is None or isinstance(cache, StaticCache) != is_static:
            cache = StaticCache() if is_static else TimeCache(self.cache_time)
            self._caches[number] = cache
        entry: Entry = (
            numbers.get(parent) or self._number(parent, insert=True),
            translation,
            rotation,
        )
        if not cache.insert(stamp, entry):
            self._error(
                "TF_OLD_DATA",
                child,
                f"TF_OLD_DATA ignoring data from the past for frame {child} at time "
                f"{display_time(stamp)} according to authority {authority}\n"
                "Possible reasons are listed at http://wiki.ros.org/tf/Errors%20explained",
                warning=True,
            )
            return False
        self._authority[number] = authority
        return True

    def _acceptable(
        self,
        parent: str,
        child: str,
        translation: tuple[float, float, float],
        rotation: Quaternion,
        norm2: float,
        authority: str,
    ) -> bool:
        """The checks of tf2's setTransform, each refusal with its line; True if none."""
        refused = False
        if child == parent:
            self._error(
                "TF_SELF_TRANSFORM",
                child,
                f'TF_SELF_TRANSFORM: Ignoring transform from authority "{authority}" with '
                f'frame_id and  child_frame_id "{child}" because they are the same',
            )
            refused = True
        if not child:
            self._error(
                "TF_NO_CHILD_FRAME_ID",
                child,
                f'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "{authority}" '
                "because child_frame_id not set ",
            )
            refused = True
        if not parent:
            self._error(
                "TF_NO_FRAME_ID",
                child,
                f'TF_NO_FRAME_ID: Ignoring transform with child_frame_id "{child}"  from '
                f'authority "{authority}" because frame_id not set',
            )
            refused = True
        values = (*translation, *rotation)
        if any(math.isnan(value) for value in values):
            shown = "({:f} {:f} {:f}) ({:f} {:f} {:f} {:f})".format(*values)
            self._error(
                "TF_NAN_INPUT",
                child,
                f'TF_NAN_INPUT: Ignoring transform for child_frame_id "{child}" from authority '
                f'"{authority}" because of a nan value in the transform {shown}',
            )
            refused = True
        if not abs(norm2 - 1.0) < QUATERNION_NORMALIZATION_TOLERANCE:
            shown = "({:f} {:f} {:f} {:f})".format(*rotation)
            self._error(
                "TF_DENORMALIZED_QUATERNION",
                child,
                f'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "{child}" '
                f'from authority "{authority}" because of an invalid quaternion in the '
                f"transform {shown}",
            )
            refused = True
        return not refused

    def _error(self, kind: str, frame: str, message: str, *, warning: bool = False) -> None:
        now = wall.monotonic()
        key = (kind, frame)
        if now - self._warned.get(key, -math.inf) < WARNING_INTERVAL:
            return
        if len(self._warned) > 4096:  # bounded: 10,000 bad frames keep at most this many
            self._warned.clear()
        self._warned[key] = now
        # tf2's core logs with no logger name, as RCUTILS_LOG_* does. Two calls: rclpy's logger
        # keeps one severity per line of code.
        if warning:
            UNNAMED_LOGGER.warning(message)
        else:
            UNNAMED_LOGGER.error(message)

    def _number(self, name: str, insert: bool = False) -> int:
        number = self._numbers.get(name, 0)
        if number == 0 and insert:
            number = len(self._names)
            self._numbers[name] = number
            self._names.append(name)
            self._caches.append(None)
        return number

    def clear(self) -> None:
        """Forget all data of the frames (static transforms stay), as tf2's clear()."""
        with self._lock:
            for cache in self._caches[1:]:
                if cache is not None:
                    cache.clear()

    # -- frame ids -----------------------------------------------------------------------------

    def _validate(self, function: str, frame: str) -> int:
        """The frame's number; raises as tf2's validateFrameId does."""
        if not frame:
            raise InvalidArgumentException(
                f'Invalid argument "{frame}" passed to {function} - '
                "in tf2 frame_ids cannot be empty"
            )
        if frame.startswith("/"):
            raise InvalidArgumentException(
                f'Invalid argument "{frame}" passed to {function} - '
                "in tf2 frame_ids cannot start with a '/'"
            )
        number = self._numbers.get(frame, 0)
        if number == 0:
            raise LookupException(f'"{frame}" passed to {function} does not exist. ')
        return number

    def _check(self, function: str, frame: str) -> tuple[int, str]:
        """The frame's number and '', or 0 and tf2's message (the canTransform flavour)."""
        rationale = ""
        if not frame:
            rationale = "in tf2 frame_ids cannot be empty"
        elif frame.startswith("/"):
            rationale = "in tf2 frame_ids cannot start with a '/'"
        elif self._numbers.get(frame, 0) == 0:
            rationale = "frame does not exist"
        if rationale:
            return 0, f'Invalid frame ID "{frame}" passed to {function} - {rationale}'
        return self._numbers[frame], ""

    def _frameExists(self, frame_id: str) -> bool:
        with self._lock:
            return frame_id in self._numbers and frame_id != NO_PARENT

    def _getFrameStrings(self) -> list[str]:
        with self._lock:
            return list(self._names[1:])

    # -- the walk ------------------------------------------------------------------------------

    def _walk(
        self, time: int, target: int, source: int, chain: list[int] | None = None
    ) -> tuple[Vector, Quaternion, int]:
        """The transform taking data in SOURCE to TARGET at TIME, and the time used; raises
        tf2's exception with tf2's message. CHAIN, if given, gets the frames on the way as tf2's
        walk records them (what tf2_monitor prints)."""
        if chain is not None:
            chain.clear()
        if source == target:
            return ZERO, IDENTITY, time
        if time == 0:
            time = self._latest_common_time(target, source)
        caches = self._caches
        # Up from the source to the root, composing source -> top.
        frame = top = source
        source_vec, source_quat = ZERO, IDENTITY
        miss: CacheMiss | None = None
        depth = 0
        while frame != 0:
            cache = caches[frame]
            if chain is not None:
                chain.append(frame)
            if cache is None:  # the root of the tree has no data of its own
                top = frame
                break
            try:
                _, (parent, translation, rotation) = cache.get_data(time)
            except CacheMiss as error:  # there may still be a way from the target
                miss, top = error, frame
                break
            if frame == target:  # the target is above the source
                return source_vec, source_quat, time
            source_vec = _add(rotate(rotation, source_vec), translation)
            source_quat = multiply(rotation, source_quat)
            top, frame = frame, parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise LookupException(_loop_message(self._frames_as_string()))
        # Up from the target until it meets that path, composing target -> top.
        frame = target
        target_vec, target_quat = ZERO, IDENTITY
        depth = 0
        down: list[int] = []
        while frame != top:
            cache = caches[frame]
            if chain is not None:
                down.append(frame)
            if cache is None:
                break
            try:
                _, (parent, translation, rotation) = cache.get_data(time)
            except CacheMiss as error:
                raise error.kind(self._on_the_way(error.message, source, target)) from None
            if frame == source:  # the source is above the target
                if chain is not None:
                    chain[:] = down
                back = inverse(target_quat)
                return rotate(back, _negative(target_vec)), back, time
            target_vec = _add(rotate(rotation, target_vec), translation)
            target_quat = multiply(rotation, target_quat)
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise LookupException(_loop_message(self._frames_as_string()))
        if frame != top:
            if miss is not None:
                raise miss.kind(self._on_the_way(miss.message, source, target))
            raise ConnectivityException(self._not_connected(source, target))
        if chain is not None:
            _join(chain, down)
        back = inverse(target_quat)
        vec = _add(rotate(back, source_vec), rotate(back, _negative(target_vec)))
        return vec, multiply(back, source_quat), time

    def _on_the_way(self, message: str, source: int, target: int) -> str:
        return (
            f"{message}, when looking up transform from frame [{self._names[source]}] "
            f"to frame [{self._names[target]}]"
        )

    def _not_connected(self, source: int, target: int) -> str:
        return (
            f"Could not find a connection between '{self._names[target]}' and "
            f"'{self._names[source]}' because they are not part of the same tree."
            "Tf has two or more unconnected trees."
        )

    def _latest_common_time(self, target: int, source: int) -> int:
        """The newest time every frame between the two has data for (0: all static)."""
        caches = self._caches
        if source == target:
            cache = caches[source]
            return cache.latest_stamp() if cache is not None else 0
        infinity = math.inf
        # From the source up: the (latest time, parent) of each frame.
        up: list[tuple[int, int]] = []
        frame, common, depth = source, infinity, 0
        while frame != 0:
            cache = caches[frame]
            if cache is None:
                break
            latest, parent = cache.latest_time_and_parent()
            if parent == 0:
                break
            if latest != 0:
                common = min(common, latest)
            up.append((latest, parent))
            frame = parent
            if frame == target:
                return 0 if common == infinity else int(common)
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise LookupException(_loop_message(self._frames_as_string()))
        # From the target up, until a parent on the source's way.
        parents = {parent for _, parent in up}
        frame, common, depth, meeting = target, infinity, 0, 0
        while True:
            cache = caches[frame]
            if cache is None:
                break
            latest, parent = cache.latest_time_and_parent()
            if parent == 0:
                break
            if latest != 0:
                common = min(common, latest)
            if parent in parents:
                meeting = parent
                break
            frame = parent
            if frame == source:
                return 0 if common == infinity else int(common)
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise LookupException(_loop_message(self._frames_as_string()))
        if meeting == 0:
            raise ConnectivityException(self._not_connected(source, target))
        for latest, parent in up:
            if latest != 0:
                common = min(common, latest)
            if parent == meeting:
                break
        return 0 if common == infinity else int(common)

    # -- lookups -------------------------------------------------------------------------------

    def _lookup(
        self, target_frame: str, source_frame: str, time: int
    ) -> tuple[Vector, Quaternion, int]:
        if target_frame == source_frame:
            if time == 0:
                cache = self._caches[self._numbers.get(target_frame, 0)]
                time = cache.latest_stamp() if cache is not None else 0
            return ZERO, IDENTITY, time
        target = self._validate("lookupTransform argument target_frame", target_frame)
        source = self._validate("lookupTransform argument source_frame", source_frame)
        return self._walk(time, target, source)

    def lookup_transform_core(self, target_frame: str, source_frame: str, time: Any) -> Any:
        """The TransformStamped that takes data in SOURCE_FRAME into TARGET_FRAME at TIME
        (rclpy Time; Time() is the latest common time)."""
        nanoseconds = to_nanoseconds(time)
        with self._lock:
            vec, quat, used = self._lookup(target_frame, source_frame, nanoseconds)
        return _message(target_frame, source_frame, vec, quat, used)

    def lookup_transform_full_core(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> Any:
        """Time travel: SOURCE_FRAME at SOURCE_TIME into TARGET_FRAME at TARGET_TIME, through
        FIXED_FRAME, which does not move in between."""
        source_ns, target_ns = to_nanoseconds(source_time), to_nanoseconds(target_time)
        with self._lock:
            for name, frame in (
                ("target_frame", target_frame),
                ("source_frame", source_frame),
                ("fixed_frame", fixed_frame),
            ):
                self._validate(f"lookupTransform argument {name}", frame)
            vec1, quat1, _ = self._lookup(fixed_frame, source_frame, source_ns)
            vec2, quat2, used = self._lookup(target_frame, fixed_frame, target_ns)
        vec = _add(rotate(quat2, vec1), vec2)
        return _message(target_frame, source_frame, vec, multiply(quat2, quat1), used)

    def can_transform_core(
        self, target_frame: str, source_frame: str, time: Any
    ) -> tuple[bool, str]:
        """(whether lookup_transform_core would succeed, tf2's message why not)."""
        nanoseconds = to_nanoseconds(time)
        if target_frame == source_frame:
            return True, ""
        with self._lock:
            return self._can(
                target_frame, source_frame, nanoseconds, "canTransform argument target_frame",
                "canTransform argument source_frame",
            )  # fmt: skip

    def _can(
        self, target_frame: str, source_frame: str, time: int, target_what: str, source_what: str
    ) -> tuple[bool, str]:
        target, message = self._check(target_what, target_frame)
        if not target:
            return False, message
        source, message = self._check(source_what, source_frame)
        if not source:
            return False, message
        try:
            self._walk(time, target, source)
        except TransformException as error:
            return False, str(error)
        return True, ""

    def can_transform_full_core(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> tuple[bool, str]:
        source_ns, target_ns = to_nanoseconds(source_time), to_nanoseconds(target_time)
        with self._lock:
            for name, frame in (
                ("target_frame", target_frame),
                ("source_frame", source_frame),
                ("fixed_frame", fixed_frame),
            ):
                number, message = self._check(f"canTransform argument {name}", frame)
                if not number:
                    return False, message
            fixed = "canTransform argument fixed_frame"
            found = self._can(
                target_frame, fixed_frame, target_ns, "canTransform argument target_frame", fixed
            )
            if not found[0]:
                return found
            return self._can(
                fixed_frame, source_frame, source_ns, fixed, "canTransform argument source_frame"
            )

    def get_latest_common_time(self, target_frame: str, source_frame: str) -> Any:
        """The rclpy Time a lookup with Time() would use."""
        with self._lock:
            target = self._validate("get_latest_common_time", target_frame)
            source = self._validate("get_latest_common_time", source_frame)
            try:
                nanoseconds = self._latest_common_time(target, source)
            except TransformException as error:
                raise TransformException(str(error)) from None
        return Time(nanoseconds=nanoseconds)

    def _chain(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> list[str]:
        """The frames a lookup goes through, as tf2's _chainAsVector lists them."""
        source_ns, target_ns = to_nanoseconds(source_time), to_nanoseconds(target_time)
        with self._lock:
            source = self._numbers.get(source_frame, 0)
            fixed = self._numbers.get(fixed_frame, 0)
            target = self._numbers.get(target_frame, 0)
            chain: list[int] = []
            self._walk(source_ns, fixed, source, chain)
            if source_ns != target_ns:
                down: list[int] = []
                self._walk(target_ns, target, fixed, down)
                m, n = len(down), len(chain)
                while m > 0 and n > 0:
                    m, n = m - 1, n - 1
                    if chain[n] != down[m]:
                        break
                if n > 0:
                    del chain[n - 1 :]
                if m < len(down):
                    chain.extend(down[: m + 1])
            return [self._names[number] for number in chain]

    # -- the frames, for people ----------------------------------------------------------------

    def all_frames_as_string(self) -> str:
        with self._lock:
            return self._frames_as_string()

    def _frames_as_string(self) -> str:
        lines = []
        for number in range(1, len(self._names)):
            cache = self._caches[number]
            if cache is None:
                continue
            parent = cache.latest_time_and_parent()[1]
            lines.append(f"Frame {self._names[number]} exists with parent {self._names[parent]}.\n")
        return "".join(lines)

    def all_frames_as_yaml(self, current_time: Any = None) -> str:
        """tf2's YAML of the frames (what the tf2_frames service and view_frames read)."""
        now = 0 if current_time is None else to_nanoseconds(current_time)
        with self._lock:
            if len(self._names) == 1:
                return "[]"
            lines = []
            for number in range(1, len(self._names)):
                cache = self._caches[number]
                if cache is None or not len(cache):
                    continue
                parent = cache.latest_time_and_parent()[1]
                authority = self._authority.get(number, "no recorded authority")
                latest, oldest = cache.latest_stamp(), cache.oldest_stamp()
                span = max(latest - oldest, 100_000)  # tf2: at least 100 microseconds
                rate = len(cache) * 1e9 / span
                lines += [
                    f"{self._names[number]}: ",
                    f"  parent: '{self._names[parent]}'",
                    f"  broadcaster: '{authority}'",
                    f"  rate: {rate:.3f}",
                    f"  most_recent_transform: {display_time(latest)}",
                    f"  oldest_transform: {display_time(oldest)}",
                ]
                if now:
                    lines.append(f"  transform_delay: {(now - latest) / NANOSECONDS:.3f}")
                lines.append(f"  buffer_length: {(latest - oldest) / NANOSECONDS:.3f}")
            return "".join(line + "\n" for line in lines)


def _join(up: list[int], down: list[int]) -> None:
    """tf2's pruning of the two halves of a walk's chain where they meet, step for step (it
    keeps neither the common frame nor, for two siblings, the source: tf2_monitor's
    "Chain is: turtle1" for turtle2 -> turtle1)."""
    m, n = len(down), len(up)
    while m > 0 and n > 0:
        m, n = m - 1, n - 1
        if up[n] != down[m]:
            break
    if n > 0:
        del up[n - 1 :]
    if m < len(down):
        up.extend(reversed(down[: m + 1]))


def _add(a: Vector, b: Vector) -> Vector:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _negative(v: Vector) -> Vector:
    return (-v[0], -v[1], -v[2])


def _message(
    target: str, source: str, vec: Vector, quat: Quaternion, time: int
) -> TransformStamped:
    message = TransformStamped()
    message.header.frame_id = target
    message.header.stamp = _stamp(time)
    message.child_frame_id = source
    t, r = message.transform.translation, message.transform.rotation
    t.x, t.y, t.z = vec
    r.x, r.y, r.z, r.w = quat
    return message
