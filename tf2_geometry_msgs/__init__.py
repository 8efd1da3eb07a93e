"""tf2_geometry_msgs: geometry_msgs' stamped types through a transform, as upstream's module.

``do_transform_point``, ``do_transform_vector3`` (rotation only), ``do_transform_pose``,
``do_transform_pose_stamped``, ``do_transform_pose_with_covariance_stamped`` (the covariance
rotated too), ``do_transform_polygon_stamped`` and ``do_transform_transform_stamped`` (as C++
tf2_geometry_msgs covers TransformStamped) each take the message and a
TransformStamped, and return a new message with the transform's header. Importing this module
registers them, which makes ``Buffer.transform()`` take those types (upstream's behaviour:
``import tf2_geometry_msgs`` before ``buffer.transform(point_stamped, 'world')``).
"""

from __future__ import annotations

import numpy as np
from geometry_msgs.msg import (
    Point32,
    PointStamped,
    PolygonStamped,
    Pose,
    PoseStamped,
    PoseWithCovarianceStamped,
    TransformStamped,
    Vector3Stamped,
)

from tf2_ros.buffer_interface import ConvertRegistration, TransformRegistration

__all__ = [
    "do_transform_point",
    "do_transform_polygon_stamped",
    "do_transform_pose",
    "do_transform_pose_stamped",
    "do_transform_pose_with_covariance_stamped",
    "do_transform_transform_stamped",
    "do_transform_vector3",
    "transform_covariance",
]


def _rotation_matrix(x: float, y: float, z: float, w: float) -> np.ndarray:
    """The 3x3 rotation of a quaternion (normalised first; identity for a zero one)."""
    norm2 = x * x + y * y + z * z + w * w
    if norm2 < np.finfo(np.float64).eps:
        return np.eye(3)
    s = 2.0 / norm2
    return np.array(
        [
            [1.0 - s * (y * y + z * z), s * (x * y - z * w), s * (x * z + y * w)],
            [s * (x * y + z * w), 1.0 - s * (x * x + z * z), s * (y * z - x * w)],
            [s * (x * z - y * w), s * (y * z + x * w), 1.0 - s * (x * x + y * y)],
        ]
    )


def _quaternion(matrix: np.ndarray) -> tuple[float, float, float, float]:
    """(x, y, z, w) of a rotation matrix, w >= 0 (Shepperd's method: the largest diagonal
    term decides the branch, so no division by a small number)."""
    m = matrix
    trace = m[0, 0] + m[1, 1] + m[2, 2]
    if trace > 0.0:
        s = 2.0 * np.sqrt(trace + 1.0)
        q = ((m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, s / 4)
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = 2.0 * np.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
        q = (s / 4, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s)
    elif m[1, 1] > m[2, 2]:
        s = 2.0 * np.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2])
        q = ((m[0, 1] + m[1, 0]) / s, s / 4, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s)
    else:
        s = 2.0 * np.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1])
        q = ((m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, s / 4, (m[1, 0] - m[0, 1]) / s)
    sign = -1.0 if q[3] < 0 else 1.0
    return tuple(float(sign * value) for value in q)  # type: ignore[return-value]


def _rotation_and_translation(transform: TransformStamped) -> tuple[np.ndarray, np.ndarray]:
    r, t = transform.transform.rotation, transform.transform.translation
    return _rotation_matrix(r.x, r.y, r.z, r.w), np.array([t.x, t.y, t.z])


def transform_covariance(cov_in: object, transform: TransformStamped) -> np.ndarray:
    """A 6x6 pose covariance (36 values, row-major) rotated into the transform's frame: each
    3x3 block B becomes R B R^T."""
    rotation, _ = _rotation_and_translation(transform)
    covariance = np.asarray(cov_in, dtype=np.float64).reshape(6, 6)
    rotate6 = np.zeros((6, 6))
    rotate6[:3, :3] = rotate6[3:, 3:] = rotation
    return (rotate6 @ covariance @ rotate6.T).reshape(36)


def do_transform_point(point: PointStamped, transform: TransformStamped) -> PointStamped:
    rotation, translation = _rotation_and_translation(transform)
    p = point.point
    x, y, z = rotation @ np.array([p.x, p.y, p.z]) + translation
    result = PointStamped(header=transform.header)
    result.point.x, result.point.y, result.point.z = float(x), float(y), float(z)
    return result


def do_transform_vector3(vector3: Vector3Stamped, transform: TransformStamped) -> Vector3Stamped:
    """A vector is a direction: rotated, not moved."""
    rotation, _ = _rotation_and_translation(transform)
    v = vector3.vector
    x, y, z = rotation @ np.array([v.x, v.y, v.z])
    result = Vector3Stamped(header=transform.header)
    result.vector.x, result.vector.y, result.vector.z = float(x), float(y), float(z)
    return result


def do_transform_pose(pose: Pose, transform: TransformStamped) -> Pose:
    rotation, translation = _rotation_and_translation(transform)
    p, o = pose.position, pose.orientation
    x, y, z = rotation @ np.array([p.x, p.y, p.z]) + translation
    orientation = rotation @ _rotation_matrix(o.x, o.y, o.z, o.w)
    result = Pose()
    result.position.x, result.position.y, result.position.z = float(x), float(y), float(z)
    q = result.orientation
    q.x, q.y, q.z, q.w = _quaternion(orientation)
    return result


def do_transform_pose_stamped(pose: PoseStamped, transform: TransformStamped) -> PoseStamped:
    return PoseStamped(header=transform.header, pose=do_transform_pose(pose.pose, transform))


def do_transform_pose_with_covariance_stamped(
    pose: PoseWithCovarianceStamped, transform: TransformStamped
) -> PoseWithCovarianceStamped:
    result = PoseWithCovarianceStamped(header=transform.header)
    result.pose.pose = do_transform_pose(pose.pose.pose, transform)
    result.pose.covariance = transform_covariance(pose.pose.covariance, transform)
    return result


def do_transform_polygon_stamped(
    polygon: PolygonStamped, transform: TransformStamped
) -> PolygonStamped:
    rotation, translation = _rotation_and_translation(transform)
    result = PolygonStamped(header=transform.header)
    for point in polygon.polygon.points:
        x, y, z = rotation @ np.array([point.x, point.y, point.z]) + translation
        result.polygon.points.append(Point32(x=float(x), y=float(y), z=float(z)))
    return result


def do_transform_transform_stamped(
    transform_in: TransformStamped, transform: TransformStamped
) -> TransformStamped:
    """A transform from the transform's frame to TRANSFORM_IN's child (C++ tf2_geometry_msgs
    covers TransformStamped; upstream's Python module does not)."""
    rotation, translation = _rotation_and_translation(transform)
    t, r = transform_in.transform.translation, transform_in.transform.rotation
    x, y, z = rotation @ np.array([t.x, t.y, t.z]) + translation
    result = TransformStamped(header=transform.header, child_frame_id=transform_in.child_frame_id)
    moved = result.transform
    moved.translation.x, moved.translation.y, moved.translation.z = float(x), float(y), float(z)
    q = moved.rotation
    q.x, q.y, q.z, q.w = _quaternion(rotation @ _rotation_matrix(r.x, r.y, r.z, r.w))
    return result


def _same_message(message: object) -> object:
    return message


_transforms = TransformRegistration()
_transforms.add(PointStamped, do_transform_point)
_transforms.add(Vector3Stamped, do_transform_vector3)
_transforms.add(PoseStamped, do_transform_pose_stamped)
_transforms.add(PoseWithCovarianceStamped, do_transform_pose_with_covariance_stamped)
_transforms.add(PolygonStamped, do_transform_polygon_stamped)
_transforms.add(TransformStamped, do_transform_transform_stamped)
_conversions = ConvertRegistration()
for _type in (Vector3Stamped, PoseStamped, PointStamped):
    _conversions.add_to_msg(_type, _same_message)
    _conversions.add_from_msg(_type, _same_message)
