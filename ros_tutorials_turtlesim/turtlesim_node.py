"""turtlesim_node: the turtle simulator of the seeds' first ROS demo, on rclpy.

(About 730 lines: the node's whole ROS side in one class, as turtlesim's own node has it,
per-turtle endpoints, node services, the rotate action, parameters and snapshots; the physics
is simulation.py's and the drawing canvas.py's.)

    turtlesim_node                                   # a window if there is a display
    turtlesim_node --ros-args -p headless:=true      # never a window
    turtlesim_node --ros-args -p snapshot_on_exit:=true -p snapshot_path:=/tmp/trail.png

Node ``turtlesim`` behaves as ROS 2 Jazzy's turtlesim (same interfaces, names, log lines):
turtle1 starts in the middle of an 11.09 m square; per turtle NAME it subscribes
``NAME/cmd_vel`` and publishes ``NAME/pose`` and ``NAME/color_sensor`` every 16 ms update, and
serves ``NAME/set_pen``, ``NAME/teleport_absolute``, ``NAME/teleport_relative`` and the action
``NAME/rotate_absolute``; the node serves ``spawn``, ``kill``, ``clear`` and ``reset``.
Parameters ``background_r/g/b`` (changeable while running) and ``holonomic``.

Added here: ``headless``, ``snapshot_path`` and ``snapshot_on_exit`` parameters, and
``~/snapshot`` (std_srvs/srv/Trigger) or SIGUSR1 to write the canvas to a PNG while running;
``headless`` says whether a window is open (true also when none could open). Any process of
the domain can set parameters and call services, so a snapshot_path set while running must be
in the folder turtlesim was started in (or be the one it was started with), and a snapshot
only ever replaces an earlier snapshot, never another file;
and ``~/_canvas/compressed`` (sensor_msgs/msg/CompressedImage, PNG): the canvas as drawn, at
most 20 frames a second and only when it changed, only while someone subscribes (the web
viewer, ``ros2 run ros_tutorials_web viewer``, shows it in a browser). Its name is hidden, so
the tools list what the tutorials show.
The simulation (``simulation.py``) is apart from the drawing (``canvas.py``).
"""

from __future__ import annotations

import contextlib
import functools
import math
import os
import re
import signal
import sys
import threading
import time
from dataclasses import dataclass, field

import rclpy
from geometry_msgs.msg import Twist
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor, SetParametersResult
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.action.server import ServerGoalHandle
from rclpy.exceptions import ParameterException
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.logging import get_logger
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.publisher import Publisher
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.service import Service
from rclpy.signals import SignalHandlerOptions
from rclpy.subscription import Subscription
from rclpy.task import Future
from sensor_msgs.msg import CompressedImage
from std_srvs.srv import Empty, Trigger
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Color, Pose
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

from ros_tutorials_common.ros import RCLError, init
from ros_tutorials_turtlesim import canvas
from ros_tutorials_turtlesim.simulation import (
    ROTATION_SPEED,
    ROTATION_TOLERANCE,
    UPDATE_PERIOD,
    WORLD_SIZE,
    Turtle,
    normalize_angle,
    to_float32,
)

DEFAULT_BACKGROUND = (69, 86, 255)  # 0x45, 0x56, 0xff
FLOAT32_MAX = 3.4028234663852886e38
REPAINT_HZ = 30
CANVAS_HZ = 20  # the most frames a second on ~/_canvas/compressed
# A frame at least this often while subscribed, changed or not: a frame published as a reader
# joins can be lost (the writer matched it before it matched the writer), and an idle turtle
# would otherwise leave the reader with none.
CANVAS_KEYFRAME = 1.0  # s
CANVAS_FORMAT = "png"  # lossless: a thin trail stays sharp (2 ms to encode, 5-20 kB)
# A turtle's name becomes part of its topic names: relative ROS name tokens, '/'-separated.
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*(/[A-Za-z][A-Za-z0-9_]*)*")
LONGEST_ENDPOINT = "rotate_absolute/_action/get_result"


def default_snapshot_name(node: str) -> str:
    """turtlesim.png for /turtlesim; for another name its own file (/turtlesim1/sim:
    turtlesim1_sim.png), so that two simulators started together do not write one file."""
    return "turtlesim.png" if node == "/turtlesim" else node.strip("/").replace("/", "_") + ".png"


def topic_qos() -> QoSProfile:
    """turtlesim's QoS for cmd_vel, pose and color_sensor: keep last 7, reliable."""
    return QoSProfile(depth=7, reliability=ReliabilityPolicy.RELIABLE)


def canvas_qos() -> QoSProfile:
    """~/_canvas/compressed: reliable, and only the newest frame is kept for a slow reader."""
    return QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE)


class WindowClosed(Exception):
    """The user closed the window: the node ends, as turtlesim does."""


@dataclass
class TurtleEndpoints:
    """One turtle's ROS endpoints, each by its name."""

    cmd_vel: Subscription
    pose: Publisher
    color_sensor: Publisher
    set_pen: Service
    teleport_absolute: Service
    teleport_relative: Service
    rotate_absolute: ActionServer

    def destroy_topics_and_services(self, node: Node) -> None:
        """All but the action server, which a kill leaves until its goal's result is out."""
        node.destroy_subscription(self.cmd_vel)
        for publisher in (self.pose, self.color_sensor):
            node.destroy_publisher(publisher)
        for service in (self.set_pen, self.teleport_absolute, self.teleport_relative):
            node.destroy_service(service)


@dataclass
class TurtleEntry:
    """One turtle, its ROS endpoints and its rotate_absolute goal."""

    turtle: Turtle
    endpoints: TurtleEndpoints = field(init=False)  # made once the entry exists (callbacks)
    goal: ServerGoalHandle | None = None
    goal_start: float = 0.0
    goal_delta: float = 0.0
    alive: bool = True  # False once killed
    executing: int = 0  # goals whose execute callback has not returned yet
    retire_at: float | None = None  # when a killed turtle's action server goes


class TurtlesimNode(Node):
    def __init__(self, **kwargs) -> None:
        super().__init__("turtlesim", enable_logger_service=True, **kwargs)
        channel = IntegerRange(from_value=0, to_value=255, step=1)
        for name, value in zip("rgb", DEFAULT_BACKGROUND, strict=True):
            self.declare_parameter(
                f"background_{name}",
                value,
                ParameterDescriptor(
                    description=f"{dict(r='Red', g='Green', b='Blue')[name]} channel of the "
                    "background color",
                    integer_range=[channel],
                ),
            )
        self.declare_parameter(
            "holonomic",
            False,
            ParameterDescriptor(description="If true, then turtles will be holonomic"),
        )
        # Declared again, read-only, once it is known whether a window opened.
        self.declare_parameter("headless", False)
        self.declare_parameter(
            "snapshot_path",
            default_snapshot_name(self.get_fully_qualified_name()),
            ParameterDescriptor(description="Where ~/snapshot, SIGUSR1 and the exit write the PNG"),
        )
        # Relative paths are relative to it; a path set while running must be in it.
        self.home = os.path.realpath(os.getcwd())
        # The path whoever started turtlesim named (command line, launch file): allowed anywhere.
        self.started_snapshot_path = os.path.abspath(self.get_parameter("snapshot_path").value)
        self.declare_parameter(
            "snapshot_on_exit",
            False,
            ParameterDescriptor(description="Write the canvas to snapshot_path when the node ends"),
        )
        # What is drawn changed: counted, so the window and the canvas topic each know
        # whether they have shown the latest.
        self._changes = 1
        self.add_on_set_parameters_callback(self._check_parameters)
        self.add_post_set_parameters_callback(self._parameters_set)
        self._parameters_set([])

        self.canvas = self._open_canvas()
        self.undeclare_parameter("headless")
        self.declare_parameter(
            "headless",
            not self.canvas.windowed,
            ParameterDescriptor(
                description="Never open a window (true also when none could open)", read_only=True
            ),
            ignore_override=True,
        )
        self.turtles: dict[str, TurtleEntry] = {}
        self._id_counter = 0  # for turtleN names
        self._spawned = 0  # for shell colours
        self._retired: list[TurtleEntry] = []  # killed, their action servers still to go
        self._painted = 0  # the window shows self._changes as it was then
        self._last_paint = -math.inf
        self._published = 0  # the canvas topic's last frame, likewise
        self._last_frame = -math.inf
        self._canvas_subscribers = 0
        self._snapshot_requested = threading.Event()
        self._lock = threading.RLock()  # SIGUSR1 and tests may ask for a PNG from elsewhere

        self.create_service(Empty, "clear", self._on_clear)
        self.create_service(Empty, "reset", self._on_reset)
        self.create_service(Spawn, "spawn", self._on_spawn)
        self.create_service(Kill, "kill", self._on_kill)
        self.create_service(Trigger, "~/snapshot", self._on_snapshot)
        # The canvas as a picture, the way ROS 2 nodes publish pictures (image_transport's
        # "compressed" topic): drawn and encoded only while someone subscribes. A hidden name
        # ('_'): `ros2 topic list`, `node info` and `bag record -a` show what the tutorials
        # show (`--include-hidden-topics` lists it).
        self.canvas_publisher = self.create_publisher(
            CompressedImage, "~/_canvas/compressed", canvas_qos()
        )

        self.get_logger().info(
            f"Starting turtlesim with node name {self.get_fully_qualified_name()}"
        )
        self.spawn_turtle("", WORLD_SIZE / 2, WORLD_SIZE / 2, 0.0)
        self.update_timer = self.create_timer(UPDATE_PERIOD, self.update)

    # --- drawing: window or headless -------------------------------------------------------

    def _open_canvas(self) -> canvas.Canvas:
        png = f"PNG of the canvas: service {self.resolve_service_name('~/snapshot')} or SIGUSR1"
        if self.get_parameter("headless").value:
            self.get_logger().info(f"Running headless (parameter headless is true); {png}")
            return canvas.Canvas(window=False)
        if not canvas.display_available():
            self.get_logger().info(
                f"Running headless (no DISPLAY or WAYLAND_DISPLAY, so no window); {png}"
            )
            return canvas.Canvas(window=False)
        try:
            drawn = canvas.Canvas(window=True)
        except Exception as error:  # pygame.error: the display named cannot be opened
            shown = ", ".join(
                f"{name}={os.environ[name]}"
                for name in ("DISPLAY", "WAYLAND_DISPLAY")
                if os.environ.get(name)
            )
            self.get_logger().warning(
                f"Running headless: no window could open on {shown} ({error}); {png}"
            )
            return canvas.Canvas(window=False)
        self.get_logger().info(
            f"Drawing in a window (pygame {canvas.pygame.version.ver}, "
            f"SDL video driver {drawn.video_driver()})"
        )
        return drawn

    def _check_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            if parameter.name == "snapshot_path" and not str(parameter.value):
                return SetParametersResult(successful=False, reason="snapshot_path is empty")
            if parameter.name == "snapshot_path":
                outside = self.snapshot_path_outside(str(parameter.value))
                if outside:
                    return SetParametersResult(successful=False, reason=outside)
        return SetParametersResult(successful=True)

    def snapshot_path_outside(self, value: str) -> str | None:
        """Why a snapshot may not be written to value (None: it may): only in the folder
        turtlesim was started in, links followed, or to the path it was started with."""
        path = os.path.abspath(value)
        if path == self.started_snapshot_path:
            return None
        if os.path.commonpath([os.path.realpath(path), self.home]) == self.home:
            return None
        return (
            f"snapshot_path {value} is outside the folder turtlesim was started in "
            f"({self.home}): only a path in there may be set while it runs"
        )

    def _parameters_set(self, _parameters: list[Parameter]) -> None:
        # Read here once, not every update: 62.5 updates/s times every turtle's colour sensor.
        self.background = tuple(self.get_parameter(f"background_{c}").value for c in "rgb")
        self.holonomic = self.get_parameter("holonomic").value
        self._changes += 1

    def request_snapshot(self) -> None:
        """Write a PNG at the next update (safe from a signal handler)."""
        self._snapshot_requested.set()

    def save_snapshot(self, path: str | None = None) -> str:
        """Write the canvas as it looks now to a PNG: to path (trusted: this process names
        it) or to snapshot_path (checked again: the folder may have changed since it was set).
        Return the absolute path; canvas.SnapshotRefused says why nothing was written."""
        if path is None:
            path = self.get_parameter("snapshot_path").value
            outside = self.snapshot_path_outside(path)
            if outside:
                raise canvas.SnapshotRefused(outside)
        path = os.path.abspath(path)
        with self._lock:
            turtles = [entry.turtle for entry in self.turtles.values()]
            picture = self.canvas.snapshot(self.background, turtles)
        canvas.write_snapshot(path, picture)
        return path

    def _write_snapshot(self) -> tuple[bool, str]:
        try:
            path = self.save_snapshot()
        except canvas.SnapshotRefused as error:
            self.get_logger().error(f"Could not write the snapshot: {error}")
            return False, str(error)
        self.get_logger().info(f"Wrote the canvas to {path}")
        return True, path

    def _on_snapshot(self, _request: Trigger.Request, response: Trigger.Response):
        response.success, response.message = self._write_snapshot()
        return response

    def close(self) -> None:
        """Destroy the node, then write the PNG if asked to and close the window.

        At exit ROS may already be shut down (Ctrl-C): the line about the PNG is then logged
        by a logger of its own, after the node (and its /rosout publisher) is gone.
        """
        path = self.get_parameter("snapshot_path").value
        outside = self.snapshot_path_outside(path)
        wanted = self.get_parameter("snapshot_on_exit").value
        logger = get_logger(self.get_name())
        # An action server holds the node: destroyed first, so that destroy_node() really
        # ends it (and its /rosout publisher) rather than later, with the line below failing.
        for entry in [*self.turtles.values(), *self._retired]:
            entry.endpoints.rotate_absolute.destroy()
        self.destroy_node()
        if wanted:
            try:
                if outside:
                    raise canvas.SnapshotRefused(outside)
                logger.info(f"Wrote the canvas to {self.save_snapshot(path)}")
            except canvas.SnapshotRefused as error:
                logger.error(f"Could not write the snapshot: {error}")
        self.canvas.close()

    # --- the update timer: what turtlesim's frame does every 16 ms ---------------------------

    def update(self) -> None:
        now = time.monotonic()
        with self._lock:
            for entry in list(self.turtles.values()):
                self._rotate(entry, now)
                turtle = entry.turtle
                old = (turtle.x, turtle.y, turtle.theta)
                strokes, hit = turtle.update(UPDATE_PERIOD, now)
                if hit is not None:
                    # upstream prints its screen coordinates (y from the top)
                    self.get_logger().warning(
                        f"Oh no! I hit the wall! (Clamping from [x={hit.x:f}, "
                        f"y={WORLD_SIZE - hit.y:f}])"
                    )
                self.canvas.draw_strokes(strokes)
                self._publish(entry)
                if strokes or old != (turtle.x, turtle.y, turtle.theta):
                    self._changes += 1
            self._retire_action_servers(now)
            if self._snapshot_requested.is_set():
                self._snapshot_requested.clear()
                self._write_snapshot()
            if self.canvas.windowed:
                if self.canvas.window_closed():
                    raise WindowClosed()
                # Repaint what changed, at most REPAINT_HZ times a second: the simulation
                # keeps its 16 ms steps even when the display is slow.
                changed = self._painted != self._changes or self.canvas.exposed
                if changed and now - self._last_paint >= 1 / REPAINT_HZ:
                    self.canvas.show(self.background, [e.turtle for e in self.turtles.values()])
                    self._painted, self._last_paint = self._changes, now
                    self.canvas.exposed = False
            # Half an update early: frames then come every 3 updates (48 ms), not 4.
            if now - self._last_frame >= 1 / CANVAS_HZ - UPDATE_PERIOD / 2:
                self._publish_canvas(now)

    def _publish_canvas(self, now: float) -> None:
        """A frame on ~/_canvas/compressed if the canvas changed, a subscriber joined, or
        CANVAS_KEYFRAME has passed since the last."""
        subscribers = self.canvas_publisher.get_subscription_count()
        joined = subscribers > self._canvas_subscribers
        self._canvas_subscribers = subscribers
        due = now - self._last_frame >= CANVAS_KEYFRAME
        if not subscribers or (self._published == self._changes and not joined and not due):
            return
        turtles = [entry.turtle for entry in self.turtles.values()]
        image = CompressedImage(format=CANVAS_FORMAT)
        image.header.stamp = self.get_clock().now().to_msg()  # when it was drawn
        image.header.frame_id = self.get_name()
        image.data = self.canvas.encode(CANVAS_FORMAT, self.background, turtles)
        self.canvas_publisher.publish(image)
        self._published, self._last_frame = self._changes, now

    def _publish(self, entry: TurtleEntry) -> None:
        """The turtle's pose and colour sensor, to whoever subscribes: a message nobody
        receives is not made (with 200 turtles, making them held the updates to 31 Hz)."""
        turtle = entry.turtle
        publisher_pose, publisher_color = entry.endpoints.pose, entry.endpoints.color_sensor
        if publisher_pose.get_subscription_count():
            publisher_pose.publish(
                Pose(
                    x=turtle.x,
                    y=turtle.y,
                    theta=turtle.theta,
                    linear_velocity=min(turtle.linear_speed, FLOAT32_MAX),
                    angular_velocity=min(max(turtle.angular, -FLOAT32_MAX), FLOAT32_MAX),
                )
            )
        if publisher_color.get_subscription_count():
            r, g, b = self.canvas.color_under(turtle.x, turtle.y, self.background)
            publisher_color.publish(Color(r=r, g=g, b=b))

    # --- spawn, kill, clear, reset -----------------------------------------------------------

    def spawn_turtle(self, name: str, x: float, y: float, theta: float) -> str:
        """Create a turtle and its endpoints; returns its name ('' if the name is taken)."""
        x, y, theta = (to_float32(v) for v in (x, y, theta))  # Spawn's fields are float32
        with self._lock:
            if not name:
                while True:
                    self._id_counter += 1
                    name = f"turtle{self._id_counter}"
                    if name not in self.turtles:
                        break
            elif name in self.turtles:
                return ""
            turtle = Turtle(name, x, y, theta, index=self._spawned)
            entry = TurtleEntry(turtle)
            entry.endpoints = self._create_endpoints(entry, name)
            self._spawned += 1
            self.turtles[name] = entry
            self._changes += 1
        self.get_logger().info(
            f"Spawning turtle [{name}] at x=[{x:f}], y=[{y:f}], theta=[{theta:f}]"
        )
        return name

    def _create_endpoints(self, entry: TurtleEntry, name: str) -> TurtleEndpoints:
        """The turtle's endpoints; should one fail, those made before it are destroyed, so
        nothing of a turtle that could not be made stays behind."""
        qos = topic_qos()
        with contextlib.ExitStack() as undo:
            cmd_vel = self.create_subscription(
                Twist, f"{name}/cmd_vel", lambda msg: self._on_cmd_vel(entry, msg), qos
            )
            undo.callback(self.destroy_subscription, cmd_vel)
            pose = self.create_publisher(Pose, f"{name}/pose", qos)
            undo.callback(self.destroy_publisher, pose)
            color_sensor = self.create_publisher(Color, f"{name}/color_sensor", qos)
            undo.callback(self.destroy_publisher, color_sensor)
            set_pen = self.create_service(
                SetPen, f"{name}/set_pen", lambda rq, rs: self._on_set_pen(entry, rq, rs)
            )
            undo.callback(self.destroy_service, set_pen)
            teleport_absolute = self.create_service(
                TeleportAbsolute,
                f"{name}/teleport_absolute",
                lambda rq, rs: self._on_teleport_absolute(entry, rq, rs),
            )
            undo.callback(self.destroy_service, teleport_absolute)
            teleport_relative = self.create_service(
                TeleportRelative,
                f"{name}/teleport_relative",
                lambda rq, rs: self._on_teleport_relative(entry, rq, rs),
            )
            undo.callback(self.destroy_service, teleport_relative)
            rotate_absolute = ActionServer(
                self,
                RotateAbsolute,
                f"{name}/rotate_absolute",
                execute_callback=functools.partial(self._execute_rotation, entry),
                goal_callback=functools.partial(self._check_rotation_goal, entry),
                handle_accepted_callback=lambda handle: self._accept_rotation(entry, handle),
                cancel_callback=lambda _handle: CancelResponse.ACCEPT,
            )
            undo.pop_all()  # all made: they stay
        return TurtleEndpoints(
            cmd_vel,
            pose,
            color_sensor,
            set_pen,
            teleport_absolute,
            teleport_relative,
            rotate_absolute,
        )

    def _name_problem(self, name: str) -> str | None:
        """Why a turtle cannot have this name (None if it can): a turtle's name is part of the
        names of its topics, services and action, which ROS bounds (247 characters in all)."""
        if not _NAME.fullmatch(name):
            return (
                "not a valid ROS name (letters, digits and '_', starting with a letter, "
                "'/' between parts)"
            )
        try:  # the longest of them: the action's hidden services
            self.resolve_service_name(f"{name}/{LONGEST_ENDPOINT}")
        except RCLError as error:
            if "length" in str(error):
                return "too long: the names of its topics and services would exceed what ROS allows"
            return str(error).split(", at ")[0]
        return None

    def kill_turtle(self, name: str) -> bool:
        with self._lock:
            entry = self.turtles.pop(name, None)
            if entry is None:
                return False
            entry.alive = False
            self._finish_rotation(entry, "abort")
            entry.endpoints.destroy_topics_and_services(self)
            # The action server goes once the goal it just ended has sent its result.
            self._retired.append(entry)
            self._changes += 1
        return True

    def _retire_action_servers(self, now: float) -> None:
        for entry in list(self._retired):
            if entry.executing:
                continue
            if entry.retire_at is None:
                entry.retire_at = now + 0.1  # a few updates for the result to go out
            elif now >= entry.retire_at:
                entry.endpoints.rotate_absolute.destroy()
                self._retired.remove(entry)

    def _on_spawn(self, request: Spawn.Request, response: Spawn.Response) -> Spawn.Response:
        if not all(math.isfinite(v) for v in (request.x, request.y, request.theta)):
            self.get_logger().error(
                f"Could not spawn turtle [{request.name}]: x, y and theta must be finite numbers"
            )
            return response
        problem = request.name and self._name_problem(request.name)
        if problem:
            self.get_logger().error(f"Could not spawn turtle [{request.name}]: {problem}")
            return response
        try:
            name = self.spawn_turtle(request.name, request.x, request.y, request.theta)
        except Exception as error:  # one bad request must not end the simulator
            self.get_logger().error(f"Could not spawn turtle [{request.name}]: {error}")
            return response
        if not name:
            self.get_logger().error(f"A turtle named [{request.name}] already exists")
        response.name = name
        return response

    def _on_kill(self, request: Kill.Request, response: Kill.Response) -> Kill.Response:
        if not self.kill_turtle(request.name):
            self.get_logger().error(f"Tried to kill turtle [{request.name}], which does not exist")
        return response

    def _on_clear(self, _request: Empty.Request, response: Empty.Response) -> Empty.Response:
        self.get_logger().info("Clearing turtlesim.")
        with self._lock:
            self.canvas.clear()
            self._changes += 1
        return response

    def _on_reset(self, _request: Empty.Request, response: Empty.Response) -> Empty.Response:
        self.get_logger().info("Resetting turtlesim.")
        with self._lock:
            for name in list(self.turtles):
                self.kill_turtle(name)
            self._id_counter = 0
            self._spawned = 0
            self.spawn_turtle("", WORLD_SIZE / 2, WORLD_SIZE / 2, 0.0)
            self.canvas.clear()
        return response

    # --- one turtle's topics and services ----------------------------------------------------

    def _on_cmd_vel(self, entry: TurtleEntry, twist: Twist) -> None:
        values = (twist.linear.x, twist.linear.y, twist.angular.z)
        if not all(math.isfinite(v) for v in values):
            self.get_logger().warning(
                f"Ignoring a velocity command for [{entry.turtle.name}] that is not finite: "
                f"linear.x={values[0]}, linear.y={values[1]}, angular.z={values[2]}",
                throttle_duration_sec=1.0,
            )
            return
        with self._lock:
            entry.turtle.command_velocity(
                values[0], values[1] if self.holonomic else 0.0, values[2], time.monotonic()
            )
            if entry.goal is not None:
                self.get_logger().warning(
                    "Velocity command received during rotation goal. Aborting goal"
                )
                self._finish_rotation(entry, "abort")

    def _on_set_pen(self, entry: TurtleEntry, request: SetPen.Request, response):
        pen = entry.turtle.pen
        pen.down = not request.off
        if request.off:
            return response
        pen.color = (request.r, request.g, request.b)
        if request.width != 0:
            pen.width = request.width
        return response

    def _refuse(self, entry: TurtleEntry, what: str, values: tuple[float, ...]) -> bool:
        if all(math.isfinite(v) for v in values):
            return False
        self.get_logger().error(
            f"Ignoring {what} for [{entry.turtle.name}]: every value must be a finite number"
        )
        return True

    def _on_teleport_absolute(self, entry: TurtleEntry, request, response):
        if not self._refuse(entry, "teleport_absolute", (request.x, request.y, request.theta)):
            with self._lock:
                entry.turtle.teleport_absolute(request.x, request.y, request.theta)
        return response

    def _on_teleport_relative(self, entry: TurtleEntry, request, response):
        if not self._refuse(entry, "teleport_relative", (request.linear, request.angular)):
            with self._lock:
                entry.turtle.teleport_relative(request.linear, request.angular)
        return response

    # --- the rotate_absolute action, stepped by the update timer like upstream ---------------

    def _check_rotation_goal(self, entry: TurtleEntry, goal: RotateAbsolute.Goal) -> GoalResponse:
        if not entry.alive:
            return GoalResponse.REJECT
        if not math.isfinite(goal.theta):
            self.get_logger().error(f"Rejecting a rotation goal of theta={goal.theta}")
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def _accept_rotation(self, entry: TurtleEntry, handle: ServerGoalHandle) -> None:
        with self._lock:
            if entry.goal is not None:
                self.get_logger().warning(
                    "Rotation goal received before a previous goal finished. Aborting previous goal"
                )
                self._finish_rotation(entry, "abort")
            handle.done = Future()  # what the execute callback waits for
            entry.goal = handle
            entry.goal_start = entry.turtle.theta
            entry.goal_delta = 0.0
            entry.executing += 1
        handle.execute()

    async def _execute_rotation(
        self, entry: TurtleEntry, handle: ServerGoalHandle
    ) -> RotateAbsolute.Result:
        # The update timer moves the turtle and ends the goal; this only waits for its result.
        try:
            return await handle.done
        finally:
            entry.executing -= 1

    def _rotate(self, entry: TurtleEntry, now: float) -> None:
        handle = entry.goal
        if handle is None:
            return
        turtle = entry.turtle
        if handle.is_cancel_requested:
            self.get_logger().info("Rotation goal canceled")
            self._finish_rotation(entry, "canceled")
            turtle.stop()
            return
        goal = normalize_angle(handle.request.theta)
        heading = to_float32(turtle.theta)
        remaining = normalize_angle(goal - heading)
        entry.goal_delta = normalize_angle(to_float32(entry.goal_start - turtle.theta))
        handle.publish_feedback(RotateAbsolute.Feedback(remaining=remaining))
        if abs(normalize_angle(heading - goal)) < ROTATION_TOLERANCE:
            self.get_logger().info("Rotation goal completed successfully")
            self._finish_rotation(entry, "succeed")
            turtle.stop()
        else:
            speed = -ROTATION_SPEED if remaining < 0 else ROTATION_SPEED
            turtle.command_velocity(0.0, 0.0, speed, now)

    def _finish_rotation(self, entry: TurtleEntry, how: str) -> None:
        handle, entry.goal = entry.goal, None
        if handle is None:
            return
        if handle.is_active:
            getattr(handle, how)()  # succeed(), canceled() or abort()
        if not handle.done.done():
            handle.done.set_result(RotateAbsolute.Result(delta=entry.goal_delta))


class StopSignals:
    """Ctrl-C and SIGTERM, noted and nothing more: the spin loop ends between two callbacks,
    never inside rclpy's own code or close(), where an exception raised by a signal can leave a
    half-made object behind (and a traceback from its __del__)."""

    def __init__(self) -> None:
        self.received: list[int] = []
        self.wake = None  # the node's guard condition, while the loop spins
        signal.signal(signal.SIGINT, self.note)
        signal.signal(signal.SIGTERM, self.note)

    def note(self, signum: int, _frame) -> None:
        if not self.received and self.wake is not None:
            self.wake.trigger()  # the executor's wait returns, the loop sees it
        self.received.append(signum)


def main(argv: list[str] | None = None) -> int:
    # Ctrl-C and SIGTERM are handled here, not by rclpy (whose handler shuts ROS down at once,
    # racing close()): the node is destroyed and the PNG written while ROS is still up.
    init(argv, signal_handler_options=SignalHandlerOptions.NO)
    stop = StopSignals()
    executor = SingleThreadedExecutor()
    node = None
    # kill -USR1 PID: a PNG now (set first: SIGUSR1's default would end the process)
    signal.signal(signal.SIGUSR1, lambda *_: node and node.request_snapshot())
    try:
        node = TurtlesimNode()
        stop.wake = node.create_guard_condition(lambda: None)
        executor.add_node(node)
        while not stop.received:
            executor.spin_once()
    except (ExternalShutdownException, WindowClosed):
        pass
    except ParameterException as error:
        raise SystemExit(f"error: {error}") from None
    finally:
        stop.wake = None  # a signal from here on wakes nothing
        if node is not None:
            node.close()
        rclpy.try_shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
