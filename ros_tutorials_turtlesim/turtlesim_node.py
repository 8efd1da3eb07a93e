"""turtlesim_node: the turtle simulator of the seeds' first ROS demo, on rclpy.

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
The parts live apart: the simulation (``simulation.py``), the drawing (``canvas.py``), one
turtle's endpoints and its rotate_absolute action (``turtle_endpoints.py``), the parameters
and the snapshot path's rule (``parameters.py``); this module joins them into the node and
its update timer, and serves the node's own services.
"""

from __future__ import annotations

import math
import os
import signal
import sys
import threading
import time

import rclpy
from rclpy.exceptions import ParameterException
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.logging import get_logger
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.signals import SignalHandlerOptions
from sensor_msgs.msg import CompressedImage
from std_srvs.srv import Empty, Trigger
from turtlesim.srv import Kill, Spawn

from ros_tutorials_common.ros import init
from ros_tutorials_common.shutdown import StopSignals, program_main
from ros_tutorials_turtlesim import canvas
from ros_tutorials_turtlesim.parameters import (
    DEFAULT_BACKGROUND,
    SnapshotPaths,
    declare_headless,
    declare_parameters,
)
from ros_tutorials_turtlesim.simulation import UPDATE_PERIOD, WORLD_SIZE, Turtle, to_float32
from ros_tutorials_turtlesim.turtle_endpoints import TurtleEndpoints, name_problem, topic_qos

__all__ = ["DEFAULT_BACKGROUND", "TurtlesimNode", "main", "topic_qos"]

REPAINT_HZ = 30
CANVAS_HZ = 20  # the most frames a second on ~/_canvas/compressed
# A frame at least this often while subscribed, changed or not: a frame published as a reader
# joins can be lost (the writer matched it before it matched the writer), and an idle turtle
# would otherwise leave the reader with none.
CANVAS_KEYFRAME = 1.0  # s
CANVAS_FORMAT = "png"  # lossless: a thin trail stays sharp (2 ms to encode, 5-20 kB)


def canvas_qos() -> QoSProfile:
    """~/_canvas/compressed: reliable, and only the newest frame is kept for a slow reader."""
    return QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE)


class WindowClosed(Exception):
    """The user closed the window: the node ends, as turtlesim does."""


class TurtlesimNode(Node):
    def __init__(self, **kwargs) -> None:
        super().__init__("turtlesim", enable_logger_service=True, **kwargs)
        declare_parameters(self)
        self.snapshot_paths = SnapshotPaths(self.get_parameter("snapshot_path").value)
        # What is drawn changed: counted, so the window and the canvas topic each know
        # whether they have shown the latest.
        self._changes = 1
        self.add_on_set_parameters_callback(self.snapshot_paths.check)
        self.add_post_set_parameters_callback(self._parameters_set)
        self._parameters_set([])

        png = f"PNG of the canvas: service {self.resolve_service_name('~/snapshot')} or SIGUSR1"
        self.canvas = canvas.open_canvas(
            self.get_logger(), self.get_parameter("headless").value, png
        )
        declare_headless(self, not self.canvas.windowed)
        self.turtles: dict[str, TurtleEndpoints] = {}
        self._id_counter = 0  # for turtleN names
        self._spawned = 0  # for shell colours
        self._retired: list[TurtleEndpoints] = []  # killed, their action servers still to go
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

    def _parameters_set(self, _parameters: list[Parameter]) -> None:
        # Read here once, not every update: 62.5 updates/s times every turtle's colour sensor.
        self.background = tuple(self.get_parameter(f"background_{c}").value for c in "rgb")
        self.holonomic = self.get_parameter("holonomic").value
        self._changes += 1

    # --- snapshots ----------------------------------------------------------------------------

    def request_snapshot(self) -> None:
        """Write a PNG at the next update (safe from a signal handler)."""
        self._snapshot_requested.set()

    def save_snapshot(self, path: str | None = None) -> str:
        """Write the canvas as it looks now to a PNG: to path (trusted: this process names
        it) or to snapshot_path (checked again: the folder may have changed since it was set).
        Return the absolute path; canvas.SnapshotRefused says why nothing was written."""
        if path is None:
            path = self.get_parameter("snapshot_path").value
            outside = self.snapshot_paths.outside(path)
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
        outside = self.snapshot_paths.outside(path)
        wanted = self.get_parameter("snapshot_on_exit").value
        logger = get_logger(self.get_name())
        # An action server holds the node: destroyed first, so that destroy_node() really
        # ends it (and its /rosout publisher) rather than later, with the line below failing.
        for entry in [*self.turtles.values(), *self._retired]:
            entry.destroy_action_server()
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
                entry.step_rotation(now)
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
                entry.publish(self._color_under)
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

    def _color_under(self, x: float, y: float) -> tuple[int, int, int]:
        return self.canvas.color_under(x, y, self.background)

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
            self.turtles[name] = TurtleEndpoints(self, turtle, self._lock, self._is_holonomic)
            self._spawned += 1
            self._changes += 1
        self.get_logger().info(
            f"Spawning turtle [{name}] at x=[{x:f}], y=[{y:f}], theta=[{theta:f}]"
        )
        return name

    def _is_holonomic(self) -> bool:
        return self.holonomic

    def kill_turtle(self, name: str) -> bool:
        with self._lock:
            entry = self.turtles.pop(name, None)
            if entry is None:
                return False
            entry.kill()
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
                entry.destroy_action_server()
                self._retired.remove(entry)

    def _on_spawn(self, request: Spawn.Request, response: Spawn.Response) -> Spawn.Response:
        if not all(math.isfinite(v) for v in (request.x, request.y, request.theta)):
            self.get_logger().error(
                f"Could not spawn turtle [{request.name}]: x, y and theta must be finite numbers"
            )
            return response
        problem = request.name and name_problem(self, request.name)
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


@program_main
def main(argv: list[str] | None = None) -> int:
    # Ctrl-C and SIGTERM are handled here, not by rclpy (whose handler shuts ROS down at once,
    # racing close()): the node is destroyed and the PNG written while ROS is still up.
    init(argv, signal_handler_options=SignalHandlerOptions.NO)
    stop = StopSignals()  # the loop ends between two callbacks, never inside close()
    executor = SingleThreadedExecutor()
    node = None
    # kill -USR1 PID: a PNG now (set first: SIGUSR1's default would end the process)
    signal.signal(signal.SIGUSR1, lambda *_: node and node.request_snapshot())
    try:
        node = TurtlesimNode()
        stop.wake = node.create_guard_condition(lambda: None).trigger
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
