"""turtlesim in-process: kinematics, the trail in the PNG, every service, the action, bad input.

The simulator runs headless in this process with a probe node beside it on one executor; the
PNG is read back with pygame and checked pixel by pixel.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator

import pygame
import pytest
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import Twist
from helpers import spin_until
from rcl_interfaces.msg import SetParametersResult
from rcl_interfaces.srv import SetParameters
from rclpy.action import ActionClient
from rclpy.node import Node
from rclpy.parameter import Parameter
from std_srvs.srv import Empty, Trigger
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Color, Pose
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

from ros_tutorials_turtlesim import canvas
from ros_tutorials_turtlesim.canvas import to_pixels
from ros_tutorials_turtlesim.draw_square import DrawSquare
from ros_tutorials_turtlesim.simulation import (
    DEFAULT_PEN,
    UPDATE_PERIOD,
    WORLD_SIZE,
    normalize_angle,
    to_float32,
)
from ros_tutorials_turtlesim.turtlesim_node import DEFAULT_BACKGROUND, TurtlesimNode, topic_qos

CENTRE = to_float32(WORLD_SIZE / 2)  # 5.544445, as turtlesim logs it


class Probe:
    """The test's own node: publishes cmd_vel, records poses and colours, calls services."""

    def __init__(self, context, executor) -> None:
        self.executor = executor
        self.node = Node("probe", context=context)
        executor.add_node(self.node)
        self.poses: dict[str, list[Pose]] = {}
        self.colors: dict[str, list[Color]] = {}
        self.publishers = {}

    def watch(self, turtle: str) -> None:
        self.poses[turtle], self.colors[turtle] = [], []
        self.node.create_subscription(Pose, f"/{turtle}/pose", self.poses[turtle].append, 1000)
        self.node.create_subscription(
            Color, f"/{turtle}/color_sensor", self.colors[turtle].append, 1000
        )
        spin_until(self.executor, lambda: self.poses[turtle], what=f"a pose of {turtle}")

    def pose(self, turtle: str = "turtle1") -> Pose:
        """The next pose published after now."""
        seen = len(self.poses[turtle])
        spin_until(self.executor, lambda: len(self.poses[turtle]) > seen, what="a new pose")
        return self.poses[turtle][-1]

    def drive(self, turtle: str, linear: float = 0.0, angular: float = 0.0, linear_y=0.0) -> None:
        if turtle not in self.publishers:
            self.publishers[turtle] = self.node.create_publisher(
                Twist, f"/{turtle}/cmd_vel", topic_qos()
            )
            spin_until(
                self.executor,
                lambda: self.publishers[turtle].get_subscription_count() > 0,
                what=f"the simulator subscribing {turtle}/cmd_vel",
            )
        twist = Twist()
        twist.linear.x, twist.linear.y, twist.angular.z = linear, linear_y, angular
        self.publishers[turtle].publish(twist)

    def call(self, srv_type, service: str, **fields):
        client = self.node.create_client(srv_type, service)
        spin_until(self.executor, client.service_is_ready, what=f"service {service}")
        future = client.call_async(srv_type.Request(**fields))
        spin_until(self.executor, future.done, what=f"the answer of {service}")
        self.node.destroy_client(client)
        return future.result()

    def wait_until_still(self, turtle: str = "turtle1") -> Pose:
        """Until the turtle has moved and stopped again (its command timed out, a goal ended)."""
        poses, start = self.poses[turtle], len(self.poses[turtle])

        def moving(pose: Pose) -> bool:
            return pose.linear_velocity != 0.0 or pose.angular_velocity != 0.0

        spin_until(self.executor, lambda: any(map(moving, poses[start:])), what="motion")
        spin_until(self.executor, lambda: not moving(poses[-1]), what=f"{turtle} to stop")
        return self.pose(turtle)

    def updates(self, count: int, turtle: str = "turtle1") -> Pose:
        """The pose count updates from now."""
        start = len(self.poses[turtle])
        spin_until(self.executor, lambda: len(self.poses[turtle]) >= start + count)
        return self.poses[turtle][-1]


@pytest.fixture
def sim(context, executor, tmp_path, monkeypatch) -> Iterator[TurtlesimNode]:
    """turtlesim started in a folder of its own (tmp_path), where its snapshots go."""
    monkeypatch.chdir(tmp_path)
    node = TurtlesimNode(context=context, parameter_overrides=[Parameter("headless", value=True)])
    executor.add_node(node)
    yield node


@pytest.fixture
def probe(context, executor, sim) -> Probe:
    probe = Probe(context, executor)
    probe.watch("turtle1")
    return probe


def png(sim: TurtlesimNode, tmp_path, name: str = "canvas.png") -> pygame.Surface:
    return pygame.image.load(sim.save_snapshot(str(tmp_path / name)))


def pixel(image: pygame.Surface, x: float, y: float) -> tuple[int, int, int]:
    px, py = to_pixels(x, y)
    return tuple(image.get_at((round(px), round(py))))[:3]


def near(image: pygame.Surface, x: float, y: float, color, radius: int = 2) -> bool:
    """Whether color is within radius pixels of (x, y) m."""
    px, py = (round(c) for c in to_pixels(x, y))
    return any(
        tuple(image.get_at((px + dx, py + dy)))[:3] == tuple(color)
        for dx in range(-radius, radius + 1)
        for dy in range(-radius, radius + 1)
    )


def test_turtle1_starts_in_the_middle_facing_east(probe):
    pose = probe.pose()
    assert (pose.x, pose.y, pose.theta) == (CENTRE, CENTRE, 0.0)
    assert (pose.linear_velocity, pose.angular_velocity) == (0.0, 0.0)
    assert probe.colors["turtle1"][-1] == Color(r=69, g=86, b=255)


def test_cmd_vel_is_integrated_16_ms_per_update_and_stops_after_1_s(probe):
    """Every pose step is whole updates of 16 ms along the commanded arc."""
    v, w = 1.0, 0.5
    probe.drive("turtle1", linear=v, angular=w)
    still = probe.wait_until_still()
    moving = [p for p in probe.poses["turtle1"] if p.linear_velocity == v]
    assert len(moving) > 10, "the turtle hardly moved"
    steps = 0
    for before, after in itertools.pairwise(moving):
        n = round(normalize_angle(after.theta - before.theta) / (w * UPDATE_PERIOD))
        assert n >= 1
        steps += n
        x, theta = before.x, before.theta
        y = before.y
        for _ in range(n):
            theta = normalize_angle(theta + w * UPDATE_PERIOD)
            x += math.cos(theta) * v * UPDATE_PERIOD
            y += math.sin(theta) * v * UPDATE_PERIOD
        assert after.x == pytest.approx(x, abs=1e-4)
        assert after.y == pytest.approx(y, abs=1e-4)
        assert after.theta == pytest.approx(theta, abs=1e-5)
    # The command is dropped 1 s after it came (at most 1 s / 16 ms = 63 updates of motion).
    assert steps <= 64
    assert still.x > CENTRE and still.y > CENTRE


@pytest.mark.long  # four sides driven in real time: 22 to 28 s
def test_draw_square_tutorial_drives_a_square_and_leaves_its_trail(
    context, executor, sim, probe, tmp_path
):
    square = DrawSquare(context=context)
    executor.add_node(square)
    goals: list[tuple[float, float]] = []

    def corners_done() -> bool:
        if square.goal is not None and (not goals or goals[-1] != (square.goal.x, square.goal.y)):
            goals.append((square.goal.x, square.goal.y))
        return square.state == "turn" and len(goals) >= 8  # four sides, four turns

    spin_until(executor, corners_done, timeout=120, what="draw_square to drive four sides")
    executor.remove_node(square)
    square.destroy_node()
    # Each turn's goal is where the side before it ended: the corners the turtle really drove
    # (draw_square stops within 0.1 m of its goal, as upstream's does).
    ideal = [(CENTRE + 2, CENTRE), (CENTRE + 2, CENTRE + 2), (CENTRE, CENTRE + 2), (CENTRE, CENTRE)]
    corners = [(CENTRE, CENTRE), *goals[1:8:2]]
    for corner, expected in zip(corners[1:], ideal, strict=True):
        assert corner == pytest.approx(expected, abs=0.2)
    pose = probe.pose()
    assert (pose.x, pose.y) == pytest.approx(corners[-1], abs=0.05)
    image = png(sim, tmp_path)
    for (x0, y0), (x1, y1) in itertools.pairwise(corners):
        for t in (0.25, 0.5, 0.75):  # along each side: the pen's colour
            x, y = x0 + (x1 - x0) * t, y0 + (y1 - y0) * t
            assert near(image, x, y, DEFAULT_PEN), f"no trail at ({x:.2f}, {y:.2f})"
    # inside and outside the square: the background
    for x, y in ((CENTRE + 1, CENTRE + 1), (1, 1), (10, 10), (CENTRE + 1, CENTRE - 1)):
        assert pixel(image, x, y) == DEFAULT_BACKGROUND


def test_spawn_names_and_refusals(sim, probe):
    assert probe.call(Spawn, "/spawn", x=3.0, y=3.0, theta=0.2, name="new_turtle").name == (
        "new_turtle"
    )
    probe.watch("new_turtle")
    pose = probe.pose("new_turtle")
    assert (pose.x, pose.y, pose.theta) == (3.0, 3.0, to_float32(0.2))
    # taken, invalid or not finite: refused with an empty name, nothing spawned
    for name, x in (("new_turtle", 1.0), ("bad name", 1.0), ("/abs", 1.0), ("9lives", 1.0)):
        assert probe.call(Spawn, "/spawn", x=x, y=1.0, theta=0.0, name=name).name == ""
    assert probe.call(Spawn, "/spawn", x=math.nan, y=1.0, theta=0.0, name="nan").name == ""
    assert probe.call(Spawn, "/spawn", x=1.0, y=math.inf, theta=0.0, name="inf").name == ""
    assert sorted(sim.turtles) == ["new_turtle", "turtle1"]
    # a name too long for its topics and services: refused, and the simulator lives on
    assert probe.call(Spawn, "/spawn", x=1.0, y=1.0, theta=0.0, name="a" * 240).name == ""
    assert sorted(sim.turtles) == ["new_turtle", "turtle1"]
    # an empty name picks turtleN
    assert probe.call(Spawn, "/spawn", x=2.0, y=2.0, theta=0.0, name="").name == "turtle2"
    # spawned outside the canvas: clamped at the first update, as turtlesim does
    assert probe.call(Spawn, "/spawn", x=50.0, y=-3.0, theta=0.0, name="far").name == "far"
    probe.watch("far")
    pose = probe.pose("far")
    assert (pose.x, pose.y) == (to_float32(WORLD_SIZE), 0.0)


def test_every_name_length_spawns_or_is_refused(sim, probe):
    """Around the length where a name stops fitting: each request is answered (a turtle, or
    an empty name), and the simulator serves the next one (ROS 2 turtlesim ends on one)."""
    spawned = []
    for length in range(190, 250, 3):
        name = "t" * length
        answer = probe.call(Spawn, "/spawn", x=1.0, y=1.0, theta=0.0, name=name).name
        assert answer in (name, ""), length
        spawned.append(bool(answer))
    assert spawned[0] and not spawned[-1], spawned
    assert probe.call(Spawn, "/spawn", x=2.0, y=2.0, theta=0.0, name="after").name == "after"


def test_kill_removes_the_turtle_and_its_topics(sim, probe, executor):
    probe.call(Spawn, "/spawn", x=3.0, y=3.0, theta=0.0, name="doomed")
    spin_until(
        executor, lambda: probe.node.count_publishers("/doomed/pose") == 1, what="doomed/pose"
    )
    probe.call(Kill, "/kill", name="doomed")
    assert "doomed" not in sim.turtles
    spin_until(executor, lambda: probe.node.count_publishers("/doomed/pose") == 0, what="pose gone")
    probe.call(Kill, "/kill", name="nobody")  # answered, nothing else happens
    assert sorted(sim.turtles) == ["turtle1"]
    probe.pose()  # the simulation goes on


def test_set_pen_colour_width_and_off(sim, probe, tmp_path):
    probe.call(SetPen, "/turtle1/set_pen", r=255, g=0, b=0, width=9, off=0)
    probe.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=2.0, y=2.0, theta=0.0)
    probe.pose()
    probe.call(SetPen, "/turtle1/set_pen", r=0, g=255, b=0, width=0, off=0)  # width kept
    probe.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=2.0, y=9.0, theta=0.0)
    probe.pose()
    probe.call(SetPen, "/turtle1/set_pen", r=0, g=0, b=0, width=3, off=1)  # lifted
    probe.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=9.0, y=9.0, theta=0.0)
    probe.pose()
    image = png(sim, tmp_path)
    middle = ((CENTRE + 2) / 2, (CENTRE + 2) / 2)
    assert pixel(image, *middle) == (255, 0, 0)
    # width 9: 2.8 px beside the (diagonal) line is still red; 8.5 px away is not
    px, py = to_pixels(*middle)
    assert tuple(image.get_at((round(px) + 2, round(py) + 2)))[:3] == (255, 0, 0)
    assert tuple(image.get_at((round(px) + 6, round(py) + 6)))[:3] == DEFAULT_BACKGROUND
    assert pixel(image, 2.0, 5.5) == (0, 255, 0)
    assert pixel(image, 5.5, 9.0) == DEFAULT_BACKGROUND  # pen off: no line


def test_teleports_and_wall_clamp(sim, probe):
    probe.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=1.0, y=2.0, theta=1.0)
    pose = probe.pose()
    assert (pose.x, pose.y, pose.theta) == pytest.approx((1.0, 2.0, 1.0), abs=1e-6)
    probe.call(TeleportRelative, "/turtle1/teleport_relative", linear=1.0, angular=0.5)
    pose = probe.pose()
    assert pose.theta == pytest.approx(1.5, abs=1e-6)
    assert (pose.x, pose.y) == pytest.approx((1 + math.cos(1.5), 2 + math.sin(1.5)), abs=1e-5)
    # into the wall: clamped to the canvas
    probe.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=-4.0, y=40.0, theta=0.0)
    pose = probe.pose()
    assert (pose.x, pose.y) == (0.0, to_float32(WORLD_SIZE))
    # driving into the wall, even absurdly fast: clamped, and the simulation goes on
    probe.drive("turtle1", linear=1e300)
    spin_until(probe.executor, lambda: probe.poses["turtle1"][-1].linear_velocity > 1e30)
    pose = probe.pose()
    assert (pose.x, pose.y) == (to_float32(WORLD_SIZE), to_float32(WORLD_SIZE))
    # not finite: refused, the turtle stays where it is
    probe.drive("turtle1", linear=math.nan)
    probe.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=math.nan, y=1.0, theta=0.0)
    probe.call(TeleportRelative, "/turtle1/teleport_relative", linear=math.inf, angular=0.0)
    pose = probe.updates(10)
    assert (pose.x, pose.y) == (to_float32(WORLD_SIZE), to_float32(WORLD_SIZE))


def test_holonomic_parameter_lets_the_turtle_move_sideways(sim, probe):
    probe.drive("turtle1", linear_y=1.0)
    pose = probe.updates(10)
    assert (pose.x, pose.y) == (CENTRE, CENTRE)  # linear.y ignored by default
    sim.set_parameters([Parameter("holonomic", value=True)])
    probe.drive("turtle1", linear_y=1.0)
    spin_until(probe.executor, lambda: probe.poses["turtle1"][-1].y > CENTRE + 0.1)
    assert probe.poses["turtle1"][-1].x == pytest.approx(CENTRE, abs=1e-5)


def test_clear_reset_and_background(sim, probe, tmp_path):
    probe.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=1.0, y=1.0, theta=0.0)
    probe.call(Spawn, "/spawn", x=3.0, y=3.0, theta=0.0, name="other")
    probe.pose()
    assert near(png(sim, tmp_path, "a.png"), 2.0, 2.0, DEFAULT_PEN)  # on the way to (1, 1)
    # background changes while running; the range 0..255 is enforced
    assert sim.set_parameters([Parameter("background_r", value=150)])[0].successful
    assert not sim.set_parameters([Parameter("background_g", value=256)])[0].successful
    image = png(sim, tmp_path, "b.png")
    assert pixel(image, 10.0, 1.0) == (150, 86, 255)
    assert near(image, 2.0, 2.0, DEFAULT_PEN)
    # clear: the trail goes, the turtles stay
    probe.call(Empty, "/clear")
    image = png(sim, tmp_path, "c.png")
    assert pixel(image, 2.0, 2.0) == (150, 86, 255)
    assert sorted(sim.turtles) == ["other", "turtle1"]
    # reset: only turtle1 again, in the middle
    probe.call(Empty, "/reset")
    assert sorted(sim.turtles) == ["turtle1"]
    pose = probe.pose()
    assert (pose.x, pose.y, pose.theta) == (CENTRE, CENTRE, 0.0)


def test_snapshot_service_writes_the_png(sim, probe, tmp_path):
    target = tmp_path / "snap.png"
    sim.set_parameters([Parameter("snapshot_path", value=str(target))])
    answer = probe.call(Trigger, "/turtlesim/snapshot")
    assert answer.success and answer.message == str(target)
    image = pygame.image.load(str(target))
    assert image.get_size() == (500, 500)
    sim.set_parameters([Parameter("snapshot_path", value=str(tmp_path / "missing" / "x.png"))])
    answer = probe.call(Trigger, "/turtlesim/snapshot")
    missing = tmp_path / "missing" / "x.png"
    assert (
        not answer.success
        and answer.message == f"cannot write {missing}: No such file or directory"
    )


def set_remotely(probe: Probe, name: str, value: str) -> SetParametersResult:
    """What `ros2 param set /turtlesim NAME VALUE` from any process of the domain does: a
    call of the node's set_parameters service."""
    message = Parameter(name, value=value).to_parameter_msg()
    return probe.call(SetParameters, "/turtlesim/set_parameters", parameters=[message]).results[0]


def test_a_snapshot_path_outside_the_start_folder_is_refused(
    sim, probe, tmp_path, tmp_path_factory
):
    """Any process of the domain (on a shared classroom machine, another user's) can set
    parameters and call services: it cannot make turtlesim write outside the folder turtlesim
    was started in, not through a link in that folder either."""
    victim = tmp_path_factory.mktemp("elsewhere") / "notes.txt"
    victim.write_text("my notes")
    (tmp_path / "link.png").symlink_to(victim)
    home = tmp_path.resolve()
    for value in (str(victim), "link.png"):
        result = set_remotely(probe, "snapshot_path", value)
        assert not result.successful
        assert result.reason == (
            f"snapshot_path {value} is outside the folder turtlesim was started in ({home}): "
            "only a path in there may be set while it runs"
        )
    assert sim.get_parameter("snapshot_path").value == "turtlesim.png"
    # A link made after the path was set: seen when the snapshot is written.
    assert set_remotely(probe, "snapshot_path", "later.png").successful
    (tmp_path / "later.png").symlink_to(victim)
    answer = probe.call(Trigger, "/turtlesim/snapshot")
    assert not answer.success
    assert answer.message.startswith("snapshot_path later.png is outside the folder")
    assert victim.read_text() == "my notes"
    # In the folder, in a folder of it: written.
    (tmp_path / "pictures").mkdir()
    assert set_remotely(probe, "snapshot_path", "pictures/one.png").successful
    answer = probe.call(Trigger, "/turtlesim/snapshot")
    assert answer.success and answer.message == str(tmp_path / "pictures" / "one.png")


def test_a_snapshot_never_replaces_another_file(sim, probe, tmp_path):
    """Only an earlier snapshot is replaced; any other file (a PNG of another program too)
    is left as it is, and the service says why."""
    notes = tmp_path / "notes.png"
    notes.write_bytes(b"not a picture")
    other = tmp_path / "other.png"
    pygame.image.save(pygame.Surface((500, 500)), str(other))
    before = other.read_bytes()
    for path in (notes, other, tmp_path):
        assert set_remotely(probe, "snapshot_path", str(path)).successful
        answer = probe.call(Trigger, "/turtlesim/snapshot")
        assert not answer.success
        assert answer.message == f"{path} exists and is not a turtlesim snapshot: not overwritten"
    assert notes.read_bytes() == b"not a picture" and other.read_bytes() == before
    assert set_remotely(probe, "snapshot_path", "snap.png").successful
    for _ in range(2):  # the second replaces the first
        assert probe.call(Trigger, "/turtlesim/snapshot").success
    assert pygame.image.load(str(tmp_path / "snap.png")).get_size() == (500, 500)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes.png", "other.png", "snap.png"]


def test_a_snapshot_that_cannot_be_written_leaves_nothing(sim, probe, tmp_path):
    """A write that fails (/dev/full, a full disk) answers success=False with the reason,
    and no partial file is left: the PNG goes to a file of its own first, renamed when whole."""
    with pytest.raises(canvas.SnapshotRefused) as refused:
        sim.save_snapshot("/dev/full")  # a path this process names: only the file rule holds
    assert str(refused.value) == "/dev/full exists and is not a turtlesim snapshot: not overwritten"
    with pytest.raises(canvas.SnapshotRefused) as refused:
        canvas.write_snapshot(str(tmp_path / "missing" / "x.png"), b"data")
    assert str(refused.value) == (
        f"cannot write {tmp_path / 'missing' / 'x.png'}: No such file or directory"
    )
    assert list(tmp_path.iterdir()) == []


def _action_graph(node: Node, turtle: str) -> str:
    """What the graph shows of a turtle's rotate_absolute: its services with their servers'
    nodes, and its topics with their publisher and subscriber counts."""
    prefix = f"/{turtle}/rotate_absolute/_action/"
    services = {
        name: [
            f"{namespace.rstrip('/')}/{server}"
            for server, namespace in node.get_node_names_and_namespaces()
            if any(
                found == name
                for found, _ in node.get_service_names_and_types_by_node(server, namespace)
            )
        ]
        for name, _ in node.get_service_names_and_types()
        if name.startswith(prefix)
    }
    topics = {
        f"{prefix}{topic}": (node.count_publishers(f"{prefix}{topic}"),
                             node.count_subscribers(f"{prefix}{topic}"))
        for topic in ("feedback", "status")
    }  # fmt: skip
    # Every node of the graph, twice if two have one name (another test's simulator not yet
    # gone: a lookup by node name then finds only one of them).
    nodes = sorted(f"{ns.rstrip('/')}/{name}" for name, ns in node.get_node_names_and_namespaces())
    return f"services {services}; topics (publishers, subscribers) {topics}; nodes {nodes}"


class Rotation:
    """A rotate_absolute goal sent by the probe, its feedback, status and result."""

    def __init__(self, probe: Probe, theta: float, turtle: str = "turtle1") -> None:
        self.probe = probe
        self.client = ActionClient(probe.node, RotateAbsolute, f"/{turtle}/rotate_absolute")
        try:
            spin_until(probe.executor, self.client.server_is_ready, what="rotate_absolute")
        except pytest.fail.Exception:  # say which part of the action the graph lacks
            pytest.fail(f"rotate_absolute never ready: {_action_graph(probe.node, turtle)}")
        self.feedback: list[float] = []
        future = self.client.send_goal_async(
            RotateAbsolute.Goal(theta=theta),
            feedback_callback=lambda msg: self.feedback.append(msg.feedback.remaining),
        )
        spin_until(probe.executor, future.done, what="the goal's response")
        self.handle = future.result()
        self.result_future = self.handle.get_result_async() if self.handle.accepted else None

    def result(self):
        spin_until(self.probe.executor, self.result_future.done, what="the rotation's result")
        answer = self.result_future.result()
        return answer.status, answer.result.delta


def test_rotate_absolute_succeeds_with_feedback(sim, probe):
    rotation = Rotation(probe, 1.0)
    # ROS 2's names for the action's parts, served by the simulator's node (an earlier
    # test's simulator may still be in the graph for a moment: a second '/turtlesim')
    shown = _action_graph(probe.node, "turtle1")
    assert "'/turtle1/rotate_absolute/_action/send_goal': ['/turtlesim'" in shown, shown
    status, delta = rotation.result()
    assert status == GoalStatus.STATUS_SUCCEEDED
    assert delta == pytest.approx(-1.0, abs=0.03)  # start minus end, as turtlesim reports
    assert rotation.feedback[0] == pytest.approx(1.0, abs=0.05)
    assert rotation.feedback == sorted(rotation.feedback, reverse=True)
    pose = probe.pose()
    assert (pose.angular_velocity, pose.theta) == (0.0, pytest.approx(1.0, abs=0.02))


def test_rotate_absolute_cancel_abort_and_replace(sim, probe):
    # cancel
    rotation = Rotation(probe, 3.0)
    spin_until(probe.executor, lambda: rotation.feedback, what="feedback")
    cancel = rotation.handle.cancel_goal_async()
    spin_until(probe.executor, cancel.done, what="the cancel's answer")
    assert rotation.result()[0] == GoalStatus.STATUS_CANCELED
    pose = probe.pose()
    assert pose.angular_velocity == 0.0 and 0.0 < pose.theta < 2.9
    # a velocity command aborts it
    rotation = Rotation(probe, -2.0)
    spin_until(probe.executor, lambda: rotation.feedback, what="feedback")
    probe.drive("turtle1", linear=0.5)
    assert rotation.result()[0] == GoalStatus.STATUS_ABORTED
    # a new goal replaces the running one
    first = Rotation(probe, 3.0)
    spin_until(probe.executor, lambda: first.feedback, what="feedback")
    second = Rotation(probe, 0.0)
    assert first.result()[0] == GoalStatus.STATUS_ABORTED
    assert second.result()[0] == GoalStatus.STATUS_SUCCEEDED
    # not a number: rejected
    assert not Rotation(probe, math.nan).handle.accepted


def test_killing_a_turtle_mid_rotation_aborts_its_goal(sim, probe):
    probe.call(Spawn, "/spawn", x=3.0, y=3.0, theta=0.0, name="spinner")
    rotation = Rotation(probe, 3.0, turtle="spinner")
    spin_until(probe.executor, lambda: rotation.feedback, what="feedback")
    probe.call(Kill, "/kill", name="spinner")
    assert rotation.result()[0] == GoalStatus.STATUS_ABORTED
    probe.pose()  # the simulation goes on


def test_color_sensor_sees_the_trail_under_the_turtle(sim, probe):
    probe.call(SetPen, "/turtle1/set_pen", r=10, g=200, b=30, width=5, off=0)
    probe.drive("turtle1", linear=1.0)
    spin_until(
        probe.executor,
        lambda: probe.colors["turtle1"][-1] == Color(r=10, g=200, b=30),
        what="the colour sensor to see the trail",
    )


def test_reset_mid_rotation_aborts_and_the_new_turtle1_takes_goals(sim, probe):
    rotation = Rotation(probe, 3.0)
    spin_until(probe.executor, lambda: rotation.feedback, what="feedback")
    probe.call(Empty, "/reset")
    assert rotation.result()[0] == GoalStatus.STATUS_ABORTED
    # the old turtle1's action server goes; the new turtle1's answers every goal
    spin_until(probe.executor, lambda: not sim._retired, what="the old action server to go")
    for theta in (1.0, -1.0):
        assert Rotation(probe, theta).result()[0] == GoalStatus.STATUS_SUCCEEDED


def test_each_simulator_has_a_snapshot_file_of_its_own(context):
    """multisim's two simulators wrote one turtlesim.png; each now names its own."""
    paths = []
    for namespace in ("turtlesim1", "turtlesim2"):
        node = TurtlesimNode(
            context=context,
            namespace=namespace,
            parameter_overrides=[Parameter("headless", value=True)],
        )
        try:
            paths.append(node.get_parameter("snapshot_path").value)
        finally:
            node.destroy_node()
    assert paths == ["turtlesim1_turtlesim.png", "turtlesim2_turtlesim.png"]
