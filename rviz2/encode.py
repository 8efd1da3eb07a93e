"""rviz2's displays, their data: each message as the 3D view's page draws it, made small. No
ROS node here (the messages are rosidl's classes, read field by field and through numpy).

Every function returns ``(header, blob)``: a JSON-able header (the message's frame, its stamp
in seconds, what the page needs) and the bulk data as bytes (or b""). Bulk is decimated so
that the page stays responsive and nothing here grows with the message: at most
``MAX_POINTS`` points of a cloud or scan, ``MAX_MAP`` cells along a map's side, ``MAX_IMAGE``
pixels along an image's side, ``MAX_MARKERS`` markers of a display and ``MAX_MARKER_POINTS``
points of one marker. Points that are not finite are dropped, as rviz drops them.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

MAX_POINTS = 100_000
MAX_MAP = 1024
MAX_IMAGE = 640
MAX_MARKERS = 10_000
MAX_MARKER_POINTS = 20_000
MAX_POSES = 10_000
MAX_TEXT = 1000


def stamp_of(header: Any) -> float:
    return header.stamp.sec + header.stamp.nanosec / 1e9


def finite(value: float) -> float:
    return float(value) if math.isfinite(value) else 0.0


def pose_of(pose: Any) -> dict[str, list[float]]:
    """geometry_msgs/Pose as [x, y, z] and a quaternion [x, y, z, w] (normalised; identity if
    it has no length, as rviz shows an invalid quaternion)."""
    p, q = pose.position, pose.orientation
    quat = [finite(q.x), finite(q.y), finite(q.z), finite(q.w)]
    norm = math.sqrt(sum(v * v for v in quat))
    quat = [v / norm for v in quat] if norm > 1e-9 else [0.0, 0.0, 0.0, 1.0]
    return {"p": [finite(p.x), finite(p.y), finite(p.z)], "q": quat}


def stride_for(count: int, limit: int) -> int:
    return max(1, math.ceil(count / limit))


def _head(msg: Any, **more: Any) -> dict[str, Any]:
    return {"frame": msg.header.frame_id, "stamp": stamp_of(msg.header), **more}


def laser_scan(msg: Any) -> tuple[dict[str, Any], bytes]:
    ranges = np.asarray(msg.ranges, dtype=np.float32)
    angles = msg.angle_min + np.arange(len(ranges), dtype=np.float64) * msg.angle_increment
    keep = np.isfinite(ranges) & (ranges >= msg.range_min) & (ranges <= msg.range_max)
    ranges, angles = ranges[keep], angles[keep]
    step = stride_for(len(ranges), MAX_POINTS)
    ranges, angles = ranges[::step], angles[::step]
    points = np.zeros((len(ranges), 3), dtype=np.float32)
    points[:, 0] = ranges * np.cos(angles)
    points[:, 1] = ranges * np.sin(angles)
    total = int(keep.size)
    return _head(msg, count=len(points), total=total, colors=False), points.tobytes()


# sensor_msgs/PointField datatypes -> numpy
FIELD_TYPES = {1: "i1", 2: "u1", 3: "i2", 4: "u2", 5: "i4", 6: "u4", 7: "f4", 8: "f8"}


def point_cloud2(msg: Any) -> tuple[dict[str, Any], bytes]:
    """x, y, z (and rgb or rgba, packed as rviz reads it) of every kept point: the positions
    as float32 triples, then the colours as uint8 triples when the cloud has them."""
    fields = {f.name: f for f in msg.fields}
    count = msg.width * msg.height
    if not all(name in fields for name in "xyz"):
        raise ValueError("a PointCloud2 without x, y and z fields")
    order = ">" if msg.is_bigendian else "<"
    names, formats, offsets = [], [], []
    for name in ("x", "y", "z", "rgb", "rgba"):
        f = fields.get(name)
        if f is None or f.datatype not in FIELD_TYPES:
            continue
        names.append(name)
        formats.append(order + ("u4" if name in ("rgb", "rgba") else FIELD_TYPES[f.datatype]))
        offsets.append(f.offset)
    if count == 0 or msg.point_step == 0:
        return _head(msg, count=0, total=0, colors=False), b""
    dtype = np.dtype({"names": names, "formats": formats, "offsets": offsets,
                      "itemsize": msg.point_step})  # fmt: skip
    data = np.frombuffer(msg.data, dtype=np.uint8)
    rows = []
    row_bytes = msg.width * msg.point_step
    if msg.row_step * msg.height > len(data) or row_bytes > msg.row_step:
        raise ValueError("a PointCloud2 whose data is shorter than its width, height and steps")
    for row in range(msg.height):
        start = row * msg.row_step
        rows.append(data[start : start + row_bytes])
    raw = np.concatenate(rows) if len(rows) > 1 else rows[0]
    step = stride_for(count, MAX_POINTS)
    points = np.frombuffer(raw.tobytes(), dtype=dtype, count=count)[::step]
    xyz = np.stack([points["x"], points["y"], points["z"]], axis=1).astype(np.float32)
    keep = np.isfinite(xyz).all(axis=1)
    xyz = xyz[keep]
    blob = xyz.tobytes()
    color_name = "rgb" if "rgb" in names else "rgba" if "rgba" in names else None
    if color_name:
        packed = points[color_name][keep].astype(np.uint32)
        rgb = np.stack([(packed >> 16) & 255, (packed >> 8) & 255, packed & 255], axis=1)
        blob += rgb.astype(np.uint8).tobytes()
    return _head(msg, count=len(xyz), total=count, colors=color_name is not None), blob


def occupancy_grid(msg: Any) -> tuple[dict[str, Any], bytes]:
    """The map's cells (0 to 100, 255 unknown), every ``step``-th along each side."""
    width, height = msg.info.width, msg.info.height
    cells = np.asarray(msg.data, dtype=np.int8)
    if width * height == 0 or len(cells) < width * height:
        raise ValueError("an OccupancyGrid whose data is shorter than width times height")
    step = stride_for(max(width, height), MAX_MAP)
    grid = cells[: width * height].reshape(height, width)[::step, ::step]
    values = grid.astype(np.uint8)  # -1 (unknown) becomes 255
    header = _head(
        msg,
        width=int(grid.shape[1]),
        height=int(grid.shape[0]),
        resolution=msg.info.resolution * step,
        origin=pose_of(msg.info.origin),
        total=[width, height],
    )
    return header, np.ascontiguousarray(values).tobytes()


IMAGE_CHANNELS = {
    "rgb8": (3, "u1"),
    "bgr8": (3, "u1"),
    "rgba8": (4, "u1"),
    "bgra8": (4, "u1"),
    "mono8": (1, "u1"),
    "8UC1": (1, "u1"),
    "mono16": (1, "u2"),
    "16UC1": (1, "u2"),
    "32FC1": (1, "f4"),
}


def image(msg: Any) -> tuple[dict[str, Any], bytes]:
    """The image as RGBA bytes, every ``step``-th pixel along each side; mono16 and float
    images scaled from their smallest to their largest value, as rviz's Image display does."""
    encoding = msg.encoding
    if encoding not in IMAGE_CHANNELS:
        raise ValueError(f"an Image of encoding {encoding!r} (shown: {', '.join(IMAGE_CHANNELS)})")
    channels, kind = IMAGE_CHANNELS[encoding]
    width, height = msg.width, msg.height
    dtype = np.dtype(kind).newbyteorder(">" if msg.is_bigendian else "<")
    row = width * channels * dtype.itemsize
    if msg.step < row or len(msg.data) < msg.step * height or width * height == 0:
        raise ValueError("an Image whose data is shorter than its step and height")
    data = np.frombuffer(bytes(msg.data), dtype=np.uint8)[: msg.step * height]
    rows = data.reshape(height, msg.step)[:, :row]
    pixels = np.frombuffer(rows.tobytes(), dtype=dtype).reshape(height, width, channels)
    step = stride_for(max(width, height), MAX_IMAGE)
    pixels = pixels[::step, ::step]
    if kind != "u1":
        values = pixels.astype(np.float64)
        finite_values = values[np.isfinite(values)]
        low, high = (finite_values.min(), finite_values.max()) if finite_values.size else (0, 1)
        values = np.nan_to_num((values - low) / max(high - low, 1e-12), nan=0.0)
        pixels = (np.clip(values, 0, 1) * 255).astype(np.uint8)
    if encoding.startswith("bgr"):
        pixels = pixels[:, :, [2, 1, 0] + ([3] if channels == 4 else [])]
    h, w = pixels.shape[:2]
    rgba = np.full((h, w, 4), 255, dtype=np.uint8)
    if channels == 1:
        rgba[:, :, :3] = pixels
    else:
        rgba[:, :, :channels] = pixels
    return _head(msg, width=int(w), height=int(h), total=[width, height]), rgba.tobytes()


def pose_stamped(msg: Any) -> tuple[dict[str, Any], bytes]:
    return _head(msg, poses=[pose_of(msg.pose)]), b""


def pose_array(msg: Any) -> tuple[dict[str, Any], bytes]:
    poses = msg.poses[:MAX_POSES]
    return _head(msg, poses=[pose_of(p) for p in poses], total=len(msg.poses)), b""


def path(msg: Any) -> tuple[dict[str, Any], bytes]:
    # Each pose of a Path is in its own header's frame; rviz draws them in the path's.
    step = stride_for(len(msg.poses), MAX_POSES)
    points = [pose_of(p.pose)["p"] for p in msg.poses[::step]]
    return _head(msg, points=points, total=len(msg.poses)), b""


def odometry(msg: Any) -> tuple[dict[str, Any], bytes]:
    return _head(msg, poses=[pose_of(msg.pose.pose)], child=msg.child_frame_id), b""


def marker(msg: Any) -> dict[str, Any]:
    """One visualization_msgs/Marker as the page draws it (its action and key included)."""
    c = msg.color
    entry: dict[str, Any] = {
        "ns": msg.ns,
        "id": msg.id,
        "action": msg.action,
        "type": msg.type,
        "frame": msg.header.frame_id,
        "stamp": stamp_of(msg.header),
        "pose": pose_of(msg.pose),
        "scale": [finite(msg.scale.x), finite(msg.scale.y), finite(msg.scale.z)],
        "color": [finite(c.r), finite(c.g), finite(c.b), finite(c.a)],
        "lifetime": msg.lifetime.sec + msg.lifetime.nanosec / 1e9,
    }
    if msg.points:
        step = stride_for(len(msg.points), MAX_MARKER_POINTS)
        entry["points"] = [[finite(p.x), finite(p.y), finite(p.z)] for p in msg.points[::step]]
        if msg.colors:
            entry["colors"] = [[finite(k.r), finite(k.g), finite(k.b), finite(k.a)]
                               for k in msg.colors[::step]]  # fmt: skip
    if msg.text:
        entry["text"] = msg.text[:MAX_TEXT]
    if msg.mesh_resource:
        entry["mesh_resource"] = msg.mesh_resource
    return entry


ENCODERS = {
    "LaserScan": laser_scan,
    "PointCloud2": point_cloud2,
    "Map": occupancy_grid,
    "Image": image,
    "Pose": pose_stamped,
    "PoseArray": pose_array,
    "Path": path,
    "Odometry": odometry,
}
