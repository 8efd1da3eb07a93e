"""One turtle's ROS side in turtlesim: its topics, services and action, each a named member.

Per turtle NAME, as ROS 2 Jazzy's turtlesim: it subscribes ``NAME/cmd_vel``, publishes
``NAME/pose`` and ``NAME/color_sensor`` at every update, serves ``NAME/set_pen``,
``NAME/teleport_absolute`` and ``NAME/teleport_relative``, and the action
``NAME/rotate_absolute``, which the simulator's update timer steps as upstream's turtle does.
The turtle's motion is simulation.py's ``Turtle``; the node (turtlesim_node.py) makes one of
these per spawned turtle and calls ``publish`` and ``step_rotation`` at every update.
"""

from __future__ import annotations

import contextlib
import math
import re
import threading
import time
from collections.abc import Callable

from geometry_msgs.msg import Twist
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.action.server import ServerGoalHandle
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.task import Future
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Color, Pose
from turtlesim.srv import SetPen, TeleportAbsolute, TeleportRelative

from ros_tutorials_common.ros import RCLError
from ros_tutorials_turtlesim.simulation import (
    ROTATION_SPEED,
    ROTATION_TOLERANCE,
    Turtle,
    normalize_angle,
    to_float32,
)

FLOAT32_MAX = 3.4028234663852886e38
# A turtle's name becomes part of its topic names: relative ROS name tokens, '/'-separated.
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*(/[A-Za-z][A-Za-z0-9_]*)*")
LONGEST_ENDPOINT = "rotate_absolute/_action/get_result"


def topic_qos() -> QoSProfile:
    """turtlesim's QoS for cmd_vel, pose and color_sensor: keep last 7, reliable."""
    return QoSProfile(depth=7, reliability=ReliabilityPolicy.RELIABLE)


def name_problem(node: Node, name: str) -> str | None:
    """Why a turtle cannot have this name (None if it can): a turtle's name is part of the
    names of its topics, services and action, which ROS bounds (247 characters in all)."""
    if not _NAME.fullmatch(name):
        return (
            "not a valid ROS name (letters, digits and '_', starting with a letter, "
            "'/' between parts)"
        )
    try:  # the longest of them: the action's hidden services
        node.resolve_service_name(f"{name}/{LONGEST_ENDPOINT}")
    except RCLError as error:
        if "length" in str(error):
            return "too long: the names of its topics and services would exceed what ROS allows"
        return str(error).split(", at ")[0]
    return None


class TurtleEndpoints:
    """One turtle, its ROS endpoints (each by its name) and its rotate_absolute goal.

    The simulator's lock guards the turtle: callbacks and the update timer take it. Should
    an endpoint fail to be made, those made before it are destroyed, so nothing of a turtle
    that could not be made stays behind.
    """

    def __init__(
        self,
        node: Node,
        turtle: Turtle,
        lock: threading.RLock,
        holonomic: Callable[[], bool],
    ) -> None:
        self.node, self.turtle, self._lock, self._holonomic = node, turtle, lock, holonomic
        self.goal: ServerGoalHandle | None = None
        self.goal_start = 0.0
        self.goal_delta = 0.0
        self.alive = True  # False once killed
        self.executing = 0  # goals whose execute callback has not returned yet
        self.retire_at: float | None = None  # when a killed turtle's action server goes
        name, qos = turtle.name, topic_qos()
        with contextlib.ExitStack() as undo:
            self.cmd_vel = node.create_subscription(Twist, f"{name}/cmd_vel", self.on_cmd_vel, qos)
            undo.callback(node.destroy_subscription, self.cmd_vel)
            self.pose = node.create_publisher(Pose, f"{name}/pose", qos)
            undo.callback(node.destroy_publisher, self.pose)
            self.color_sensor = node.create_publisher(Color, f"{name}/color_sensor", qos)
            undo.callback(node.destroy_publisher, self.color_sensor)
            self.set_pen = node.create_service(SetPen, f"{name}/set_pen", self.on_set_pen)
            undo.callback(node.destroy_service, self.set_pen)
            self.teleport_absolute = node.create_service(
                TeleportAbsolute, f"{name}/teleport_absolute", self.on_teleport_absolute
            )
            undo.callback(node.destroy_service, self.teleport_absolute)
            self.teleport_relative = node.create_service(
                TeleportRelative, f"{name}/teleport_relative", self.on_teleport_relative
            )
            undo.callback(node.destroy_service, self.teleport_relative)
            self.rotate_absolute = ActionServer(
                node,
                RotateAbsolute,
                f"{name}/rotate_absolute",
                execute_callback=self.execute_rotation,
                goal_callback=self.check_rotation_goal,
                handle_accepted_callback=self.accept_rotation,
                cancel_callback=lambda _handle: CancelResponse.ACCEPT,
            )
            undo.pop_all()  # all made: they stay

    def publish(self, color_under: Callable[[float, float], tuple[int, int, int]]) -> None:
        """The turtle's pose and colour sensor, to whoever subscribes: a message nobody
        receives is not made (with 200 turtles, making them held the updates to 31 Hz)."""
        turtle = self.turtle
        if self.pose.get_subscription_count():
            self.pose.publish(
                Pose(
                    x=turtle.x,
                    y=turtle.y,
                    theta=turtle.theta,
                    linear_velocity=min(turtle.linear_speed, FLOAT32_MAX),
                    angular_velocity=min(max(turtle.angular, -FLOAT32_MAX), FLOAT32_MAX),
                )
            )
        if self.color_sensor.get_subscription_count():
            r, g, b = color_under(turtle.x, turtle.y)
            self.color_sensor.publish(Color(r=r, g=g, b=b))

    def kill(self) -> None:
        """The turtle is gone: its goal aborted, its topics and services destroyed. The action
        server stays until the goal it just ended has sent its result (destroy_action_server)."""
        self.alive = False
        self.finish_rotation("abort")
        node = self.node
        node.destroy_subscription(self.cmd_vel)
        for publisher in (self.pose, self.color_sensor):
            node.destroy_publisher(publisher)
        for service in (self.set_pen, self.teleport_absolute, self.teleport_relative):
            node.destroy_service(service)

    def destroy_action_server(self) -> None:
        self.rotate_absolute.destroy()

    # --- the topic and services ----------------------------------------------------------

    def on_cmd_vel(self, twist: Twist) -> None:
        values = (twist.linear.x, twist.linear.y, twist.angular.z)
        if not all(math.isfinite(v) for v in values):
            self.node.get_logger().warning(
                f"Ignoring a velocity command for [{self.turtle.name}] that is not finite: "
                f"linear.x={values[0]}, linear.y={values[1]}, angular.z={values[2]}",
                throttle_duration_sec=1.0,
            )
            return
        with self._lock:
            self.turtle.command_velocity(
                values[0], values[1] if self._holonomic() else 0.0, values[2], time.monotonic()
            )
            if self.goal is not None:
                self.node.get_logger().warning(
                    "Velocity command received during rotation goal. Aborting goal"
                )
                self.finish_rotation("abort")

    def on_set_pen(self, request: SetPen.Request, response: SetPen.Response) -> SetPen.Response:
        pen = self.turtle.pen
        pen.down = not request.off
        if request.off:
            return response
        pen.color = (request.r, request.g, request.b)
        if request.width != 0:
            pen.width = request.width
        return response

    def _refuse(self, what: str, values: tuple[float, ...]) -> bool:
        if all(math.isfinite(v) for v in values):
            return False
        self.node.get_logger().error(
            f"Ignoring {what} for [{self.turtle.name}]: every value must be a finite number"
        )
        return True

    def on_teleport_absolute(self, request, response):
        if not self._refuse("teleport_absolute", (request.x, request.y, request.theta)):
            with self._lock:
                self.turtle.teleport_absolute(request.x, request.y, request.theta)
        return response

    def on_teleport_relative(self, request, response):
        if not self._refuse("teleport_relative", (request.linear, request.angular)):
            with self._lock:
                self.turtle.teleport_relative(request.linear, request.angular)
        return response

    # --- the rotate_absolute action, stepped by the update timer like upstream -----------

    def check_rotation_goal(self, goal: RotateAbsolute.Goal) -> GoalResponse:
        if not self.alive:
            return GoalResponse.REJECT
        if not math.isfinite(goal.theta):
            self.node.get_logger().error(f"Rejecting a rotation goal of theta={goal.theta}")
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def accept_rotation(self, handle: ServerGoalHandle) -> None:
        with self._lock:
            if self.goal is not None:
                self.node.get_logger().warning(
                    "Rotation goal received before a previous goal finished. Aborting previous goal"
                )
                self.finish_rotation("abort")
            handle.done = Future()  # what the execute callback waits for
            self.goal = handle
            self.goal_start = self.turtle.theta
            self.goal_delta = 0.0
            self.executing += 1
        handle.execute()

    async def execute_rotation(self, handle: ServerGoalHandle) -> RotateAbsolute.Result:
        # The update timer moves the turtle and ends the goal; this only waits for its result.
        try:
            return await handle.done
        finally:
            self.executing -= 1

    def step_rotation(self, now: float) -> None:
        """One update of the goal: feedback, then done or turning on (under the lock)."""
        handle = self.goal
        if handle is None:
            return
        turtle = self.turtle
        if handle.is_cancel_requested:
            self.node.get_logger().info("Rotation goal canceled")
            self.finish_rotation("canceled")
            turtle.stop()
            return
        goal = normalize_angle(handle.request.theta)
        heading = to_float32(turtle.theta)
        remaining = normalize_angle(goal - heading)
        self.goal_delta = normalize_angle(to_float32(self.goal_start - turtle.theta))
        handle.publish_feedback(RotateAbsolute.Feedback(remaining=remaining))
        if abs(normalize_angle(heading - goal)) < ROTATION_TOLERANCE:
            self.node.get_logger().info("Rotation goal completed successfully")
            self.finish_rotation("succeed")
            turtle.stop()
        else:
            speed = -ROTATION_SPEED if remaining < 0 else ROTATION_SPEED
            turtle.command_velocity(0.0, 0.0, speed, now)

    def finish_rotation(self, how: str) -> None:
        handle, self.goal = self.goal, None
        if handle is None:
            return
        if handle.is_active:
            getattr(handle, how)()  # succeed(), canceled() or abort()
        if not handle.done.done():
            handle.done.set_result(RotateAbsolute.Result(delta=self.goal_delta))
