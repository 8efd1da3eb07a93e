"""The turtles' world, apart from ROS and apart from drawing (as ROS 2 turtlesim splits it).

A Turtle knows its pose, its last velocity command, its pen and its queued teleports. One
``update(dt)`` step does what turtlesim's update timer does for each turtle: teleports first,
then the velocity command (dropped when older than 1 s), the wall clamp, and the pen strokes it
leaves behind, which the caller hands to the canvas. Nothing here imports rclpy or pygame, so
the kinematics are testable on their own and the same with or without a window.

Coordinates are turtlesim's: metres, origin at the bottom-left corner, y up, theta in
[-pi, pi) with 0 pointing east.
"""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass, field

CANVAS_PIXELS = 500
METER_PIXELS = 45  # one metre is the height of turtlesim's turtle image
WORLD_SIZE = (CANVAS_PIXELS - 1) / METER_PIXELS  # 11.0889 m, the same both ways
UPDATE_PERIOD = 0.016  # s; turtlesim's update timer, and the step each update integrates
COMMAND_TIMEOUT = 1.0  # s; an older velocity command stops the turtle
ROTATION_SPEED = 1.0  # rad/s, for rotate_absolute
ROTATION_TOLERANCE = 0.02  # rad, when rotate_absolute has arrived

DEFAULT_PEN = (0xB3, 0xB8, 0xFF)
DEFAULT_PEN_WIDTH = 3


def normalize_angle(angle: float) -> float:
    """The same angle in [-pi, pi)."""
    return angle - 2 * math.pi * math.floor((angle + math.pi) / (2 * math.pi))


def to_float32(value: float) -> float:
    """What a float32 message field holds (the pose is published as float32)."""
    return struct.unpack("f", struct.pack("f", value))[0]


@dataclass
class Pen:
    color: tuple[int, int, int] = DEFAULT_PEN
    width: int = DEFAULT_PEN_WIDTH
    down: bool = True


@dataclass
class Stroke:
    """A line the pen drew, in metres (canvas coordinates, y up)."""

    start: tuple[float, float]
    end: tuple[float, float]
    color: tuple[int, int, int]
    width: int


@dataclass
class WallHit:
    """Where the turtle would have gone before it was clamped to the canvas."""

    x: float
    y: float


@dataclass
class AbsoluteTeleport:
    """A queued teleport_absolute: to this pose."""

    x: float
    y: float
    theta: float


@dataclass
class RelativeTeleport:
    """A queued teleport_relative: turn by angular, then move linear along the new heading."""

    linear: float
    angular: float


@dataclass
class Turtle:
    name: str
    x: float
    y: float
    theta: float
    index: int = 0  # which shell colour the canvas gives it
    linear_x: float = 0.0
    linear_y: float = 0.0
    angular: float = 0.0
    last_command: float = -math.inf  # time of the last velocity command (s, any clock)
    pen: Pen = field(default_factory=Pen)
    teleports: list[AbsoluteTeleport | RelativeTeleport] = field(default_factory=list)

    def command_velocity(
        self, linear_x: float, linear_y: float, angular: float, now: float
    ) -> None:
        self.linear_x, self.linear_y, self.angular = linear_x, linear_y, angular
        self.last_command = now

    def stop(self) -> None:
        self.linear_x = self.linear_y = self.angular = 0.0

    def teleport_absolute(self, x: float, y: float, theta: float) -> None:
        """Queued, and done at the next update (as turtlesim does)."""
        self.teleports.append(AbsoluteTeleport(x, y, theta))

    def teleport_relative(self, linear: float, angular: float) -> None:
        self.teleports.append(RelativeTeleport(linear, angular))

    @property
    def linear_speed(self) -> float:
        return math.hypot(self.linear_x, self.linear_y)

    def update(self, dt: float, now: float) -> tuple[list[Stroke], WallHit | None]:
        """One simulation step of dt seconds; returns the pen strokes and any wall hit."""
        strokes = []
        for teleport in self.teleports:
            start = (self.x, self.y)
            if isinstance(teleport, RelativeTeleport):
                self.theta += teleport.angular
                self.x += math.cos(self.theta) * teleport.linear
                self.y += math.sin(self.theta) * teleport.linear
            else:
                # as turtlesim: y is kept below the top edge here, the rest is clamped below
                self.x, self.y = teleport.x, min(teleport.y, WORLD_SIZE)
                self.theta = teleport.theta
            strokes += self._draw(start)
        self.teleports.clear()

        if now - self.last_command > COMMAND_TIMEOUT:
            self.stop()

        start = (self.x, self.y)
        self.theta = normalize_angle(self.theta + self.angular * dt)
        cos, sin = math.cos(self.theta), math.sin(self.theta)
        self.x += (cos * self.linear_x - sin * self.linear_y) * dt
        self.y += (sin * self.linear_x + cos * self.linear_y) * dt

        hit = None
        if not (0.0 <= self.x <= WORLD_SIZE and 0.0 <= self.y <= WORLD_SIZE):
            hit = WallHit(self.x, self.y)
            self.x = min(max(self.x, 0.0), WORLD_SIZE)
            self.y = min(max(self.y, 0.0), WORLD_SIZE)
        if (self.x, self.y) != start:
            strokes += self._draw(start)
        return strokes, hit

    def _draw(self, start: tuple[float, float]) -> list[Stroke]:
        if not self.pen.down:
            return []
        return [Stroke(start, (self.x, self.y), self.pen.color, self.pen.width)]
