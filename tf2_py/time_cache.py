"""The data of one frame over time, as tf2's TimeCache and StaticCache keep it.

A TimeCache holds a frame's transforms to its parent for ``max_storage`` nanoseconds before its
newest one (tf2's default: 10 s); older entries are dropped on each insert, so a fast
broadcaster holds at most that much. Between two entries with the same parent, translation is
interpolated linearly and rotation by slerp; past the newest or before the oldest entry it
fails with tf2's extrapolation messages. A StaticCache holds one transform, valid at any time.

Times are integer nanoseconds; 0 means "the latest". Rotations are unit quaternions as tuples
(x, y, z, w), in plain Python floats (ros_tutorials_common/quaternion.py has their product and
rotation).
"""

from __future__ import annotations

import math
from array import array
from bisect import bisect_right

from ros_tutorials_common.quaternion import Quaternion, Vector
from tf2_py.exceptions import ExtrapolationException, TransformException

# (parent frame number, translation, rotation): one transform of a frame to its parent.
Entry = tuple[int, Vector, Quaternion]
IDENTITY: Quaternion = (0.0, 0.0, 0.0, 1.0)
ZERO: Vector = (0.0, 0.0, 0.0)
NANOSECONDS = 1_000_000_000
WIDTH = 7  # the values of one entry in TimeCache's array: translation and rotation


def display_time(nanoseconds: int) -> str:
    """A time as tf2 prints one in its messages: seconds with 6 decimals."""
    seconds, rest = divmod(nanoseconds, NANOSECONDS)
    return f"{seconds + rest * 1e-9:.6f}"


def inverse(q: Quaternion) -> Quaternion:
    return (-q[0], -q[1], -q[2], q[3])


def normalized(q: Quaternion) -> Quaternion:
    norm = math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3])
    return (q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm)


def slerp(a: Quaternion, b: Quaternion, ratio: float) -> Quaternion:
    """Spherical interpolation from a (ratio 0) to b (ratio 1), the shorter way round."""
    dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]
    sign = -1.0 if dot < 0.0 else 1.0
    dot *= sign
    if dot >= 1.0 - 1e-12:  # the same rotation: nothing to interpolate
        return a
    theta = math.acos(dot)
    scale = 1.0 / math.sin(theta)
    s0 = math.sin((1.0 - ratio) * theta) * scale
    s1 = math.sin(ratio * theta) * scale * sign
    return (
        a[0] * s0 + b[0] * s1,
        a[1] * s0 + b[1] * s1,
        a[2] * s0 + b[2] * s1,
        a[3] * s0 + b[3] * s1,
    )


class CacheMiss(Exception):
    """No data for the time asked; ``kind`` is the exception tf2 would raise for it."""

    def __init__(self, message: str, kind: type[TransformException] = ExtrapolationException):
        super().__init__(message)
        self.message = message
        self.kind = kind


class TimeCache:
    """A frame's transforms over the last ``max_storage`` nanoseconds, oldest first.

    Kept in flat arrays (stamps, parents, and seven doubles a transform: translation, rotation),
    not as Python objects: a fast broadcaster's 10 s of data is then a few arrays rather than
    a million tuples and floats, each allocated on insert and freed when pruned."""

    __slots__ = ("_parents", "_stamps", "_start", "_values", "max_storage")

    def __init__(self, max_storage: int) -> None:
        self.max_storage = max_storage
        self._stamps = array("q")
        self._parents = array("q")
        self._values = array("d")  # WIDTH values an entry: x, y, z, qx, qy, qz, qw
        self._start = 0  # entries before this are pruned, removed in bulk (see _prune)

    def __len__(self) -> int:
        return len(self._stamps) - self._start

    def _entry(self, index: int) -> Entry:
        v, at = self._values, index * WIDTH
        return self._parents[index], (v[at], v[at + 1], v[at + 2]), tuple(v[at + 3 : at + 7])

    def insert(self, stamp: int, entry: Entry) -> bool:
        """Add a transform; False when it is older than the cache keeps (tf2's TF_OLD_DATA)."""
        stamps = self._stamps
        if len(stamps) > self._start:
            horizon = stamps[-1] - self.max_storage
            if stamps[self._start] < horizon:
                self._prune(horizon)
            if stamp < horizon:
                return False
        end = len(stamps)  # after _prune, which may have dropped the pruned entries
        if not end or stamp >= stamps[-1]:
            position = end
        else:
            position = bisect_right(stamps, stamp, self._start)
        same = position - 1
        while same >= self._start and stamps[same] == stamp:
            if self._entry(same) == entry:
                return True  # the very same data again: kept once, as tf2 does
            same -= 1
        parent, translation, rotation = entry
        if position == end:
            stamps.append(stamp)
            self._parents.append(parent)
            self._values.extend(translation)
            self._values.extend(rotation)
        else:
            stamps.insert(position, stamp)
            self._parents.insert(position, parent)
            at = position * WIDTH
            self._values[at:at] = array("d", (*translation, *rotation))
        return True

    def _prune(self, horizon: int) -> None:
        stamps, start = self._stamps, self._start
        while start < len(stamps) and stamps[start] < horizon:
            start += 1
        # Drop the pruned entries when they are half the arrays: memory stays within twice the
        # cache, and a fast broadcaster does not pay a shift on every message.
        if start > 32 and 2 * start > len(stamps):
            del stamps[:start]
            del self._parents[:start]
            del self._values[: start * WIDTH]
            start = 0
        self._start = start

    def get_data(self, time: int) -> tuple[int, Entry]:
        """(stamp, entry) at TIME (0: the newest), interpolated between two entries with one
        parent; raises CacheMiss with tf2's message when TIME is outside the data."""
        stamps, start = self._stamps, self._start
        last = len(stamps) - 1
        if start > last:
            raise CacheMiss("")  # tf2 says nothing more for an empty cache
        if time == 0:
            return stamps[last], self._entry(last)
        if last == start:
            if stamps[start] == time:
                return time, self._entry(start)
            raise CacheMiss(
                f"Lookup would require extrapolation at time {display_time(time)}, "
                f"but only time {display_time(stamps[start])} is in the buffer"
            )
        latest, earliest = stamps[last], stamps[start]
        if time == latest:
            return time, self._entry(last)
        if time == earliest:
            return time, self._entry(start)
        if time > latest:
            raise CacheMiss(
                "Lookup would require extrapolation into the future.  Requested time "
                f"{display_time(time)} but the latest data is at time {display_time(latest)}"
            )
        if time < earliest:
            raise CacheMiss(
                "Lookup would require extrapolation into the past.  Requested time "
                f"{display_time(time)} but the earliest data is at time {display_time(earliest)}"
            )
        newer = bisect_right(stamps, time, start)
        older = newer - 1
        old, new = self._entry(older), self._entry(newer)
        if old[0] != new[0]:  # the parent changed in between: the older data holds
            return stamps[older], old
        span = stamps[newer] - stamps[older]
        if span == 0:
            return stamps[newer], new
        ratio = (time - stamps[older]) / span
        (ox, oy, oz), (nx, ny, nz) = old[1], new[1]
        translation = (ox + (nx - ox) * ratio, oy + (ny - oy) * ratio, oz + (nz - oz) * ratio)
        return time, (old[0], translation, slerp(old[2], new[2], ratio))

    def latest_time_and_parent(self) -> tuple[int, int]:
        if self._start == len(self._stamps):
            return 0, 0
        return self._stamps[-1], self._parents[-1]

    def latest_stamp(self) -> int:
        return self._stamps[-1] if len(self) else 0

    def oldest_stamp(self) -> int:
        return self._stamps[self._start] if len(self) else 0

    def clear(self) -> None:
        del self._stamps[:]
        del self._parents[:]
        del self._values[:]
        self._start = 0


class StaticCache:
    """A static frame's one transform, valid at every time (its stamps read as 0)."""

    __slots__ = ("_entry",)

    def __init__(self) -> None:
        self._entry: Entry = (0, ZERO, IDENTITY)

    def __len__(self) -> int:
        return 1

    def insert(self, stamp: int, entry: Entry) -> bool:
        self._entry = entry
        return True

    def get_data(self, time: int) -> tuple[int, Entry]:
        return time, self._entry

    def latest_time_and_parent(self) -> tuple[int, int]:
        return 0, self._entry[0]

    def latest_stamp(self) -> int:
        return 0

    def oldest_stamp(self) -> int:
        return 0

    def clear(self) -> None:
        """tf2 keeps a static transform through clear()."""
