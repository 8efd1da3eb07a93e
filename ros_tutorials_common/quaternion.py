"""Rotations as unit quaternions (x, y, z, w) in plain Python floats, which for 3- and 4-vectors
is faster than numpy's per-call overhead: what tf2's core (tf2_py), its static transform
publisher and the URDF model (urdf.py) compute with."""

from __future__ import annotations

import math

Vector = tuple[float, float, float]
Quaternion = tuple[float, float, float, float]  # x, y, z, w


def quaternion_from_rpy(roll: float, pitch: float, yaw: float) -> Quaternion:
    """Roll about x, then pitch about y, then yaw about z, all fixed axes (URDF's rpy, tf2's
    Euler angles)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
        cr * cp * cy + sr * sp * sy,
    )


def multiply(a: Quaternion, b: Quaternion) -> Quaternion:
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def rotate(q: Quaternion, v: Vector) -> Vector:
    """v rotated by the unit quaternion q (v + 2w(u x v) + 2u x (u x v), u = q's vector)."""
    x, y, z, w = q
    vx, vy, vz = v
    cx = 2.0 * (y * vz - z * vy)
    cy = 2.0 * (z * vx - x * vz)
    cz = 2.0 * (x * vy - y * vx)
    return (
        vx + w * cx + (y * cz - z * cy),
        vy + w * cy + (z * cx - x * cz),
        vz + w * cz + (x * cy - y * cx),
    )
