"""turtle_tf2_py's follow loop: from turtle1's pose message to the listener's cmd_vel for turtle2.

The demo's own nodes run as processes (the two turtle_tf2_broadcasters, turtle_tf2_listener);
this process stands in for turtlesim: it answers /spawn, publishes both turtles' poses at
turtlesim's 62.5 Hz and moves turtle1 between two places, 2 m ahead of turtle2 and 2 m to its
left, so that the listener's turn command (angular.z: 0, then pi/2) tells which pose it saw.

- loop: from the first pose at the new place to the first cmd_vel that turns the new way;
- timer phase (the baseline): from the same pose to the first cmd_vel at all: the listener
  looks up once a second (its timer, as on the page), so this is what the loop cannot beat;
  the ratio says how often the transform had not yet reached the listener's buffer by then;
- broadcast hop: from the pose to the broadcaster's /tf message that carries it.
"""

from __future__ import annotations

import math
import random
import threading
import time

import rclpy
from geometry_msgs.msg import Twist
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from tf2_msgs.msg import TFMessage
from turtlesim.msg import Pose
from turtlesim.srv import Spawn

from benchmarks.common import Row, fmt_ms, p50, p99, python, smoke, start, stop
from ros_tutorials_common import wait

STEPS = smoke(20, 2)
POSE_PERIOD = 0.016  # turtlesim's
TURTLE2 = (4.0, 2.0)  # where the listener spawns it, facing +x
PLACES = [((6.0, 2.0), 0.0), ((4.0, 4.0), math.pi / 2)]  # turtle1's place, the turn it asks


class FakeTurtlesim:
    def __init__(self, context) -> None:
        self.node = Node("tf2_follow_bench", context=context)
        self.executor = SingleThreadedExecutor(context=context)
        self.executor.add_node(self.node)
        self.place = 0
        self.moved_at: float | None = None  # the first pose at the new place went out
        self.first_cmd: float | None = None
        self.turned: float | None = None
        self.broadcast: float | None = None
        self.spawned = False
        self.poses = {
            name: self.node.create_publisher(Pose, f"/{name}/pose", 1)
            for name in ("turtle1", "turtle2")
        }
        self.node.create_service(Spawn, "/spawn", self.spawn)
        self.node.create_subscription(Twist, "/turtle2/cmd_vel", self.on_cmd_vel, 10)
        self.node.create_subscription(TFMessage, "/tf", self.on_tf, 100)
        self.node.create_timer(POSE_PERIOD, self.publish_poses)

    def spawn(self, request: Spawn.Request, response: Spawn.Response) -> Spawn.Response:
        self.spawned = True
        response.name = request.name
        return response

    def publish_poses(self) -> None:
        (x, y), _ = PLACES[self.place]
        self.poses["turtle1"].publish(Pose(x=x, y=y))
        if self.moved_at is None:
            self.moved_at = time.monotonic()
        if self.spawned:
            self.poses["turtle2"].publish(Pose(x=TURTLE2[0], y=TURTLE2[1]))

    def on_cmd_vel(self, twist: Twist) -> None:
        if self.moved_at is None:
            return
        now = time.monotonic()
        if self.first_cmd is None:
            self.first_cmd = now
        if self.turned is None and abs(twist.angular.z - PLACES[self.place][1]) < 1e-3:
            self.turned = now

    def on_tf(self, message: TFMessage) -> None:
        (x, y), _ = PLACES[self.place]
        for t in message.transforms:
            at = (t.transform.translation.x, t.transform.translation.y)
            if t.child_frame_id == "turtle1" and at == (x, y) and self.broadcast is None:
                self.broadcast = time.monotonic()

    def move(self) -> None:
        self.place = 1 - self.place
        self.moved_at = self.first_cmd = self.turned = self.broadcast = None

    def spin_until(self, condition, timeout: float, what: str) -> None:
        if not wait.spin_until(self.executor, condition, timeout, period=0.01):
            raise RuntimeError(f"tf2 follow benchmark: timed out waiting for {what}")


def follow_loop(steps: int = STEPS) -> list[Row]:
    commands = [
        python("-m", "turtle_tf2_py.turtle_tf2_broadcaster", "--ros-args", "-p", f"turtlename:={n}")
        for n in ("turtle1", "turtle2")
    ] + [python("-m", "turtle_tf2_py.turtle_tf2_listener")]
    procs = [start(command) for command in commands]
    for proc in procs:  # their log lines are not needed, but the pipes must never fill
        threading.Thread(target=proc.stdout.read, daemon=True).start()
    context = rclpy.Context()
    rclpy.init(context=context)
    sim = FakeTurtlesim(context)
    loop, phase, hop = [], [], []
    try:
        sim.spin_until(lambda: sim.turned is not None, 120.0, "the listener's first command")
        rng = random.Random(38)
        for _ in range(steps):
            # at a random moment of the listener's second, not right after its tick
            pause = time.monotonic() + rng.uniform(0.0, 1.0)
            sim.spin_until(lambda pause=pause: time.monotonic() >= pause, 5.0, "the pause")
            sim.move()
            sim.spin_until(lambda: sim.turned is not None, 30.0, "turtle2's turn")
            loop.append(sim.turned - sim.moved_at)
            phase.append(sim.first_cmd - sim.moved_at)
            if sim.broadcast is not None:
                hop.append(sim.broadcast - sim.moved_at)
    finally:
        sim.executor.shutdown()
        sim.node.destroy_node()
        context.try_shutdown()
        for proc in procs:
            stop(proc)
    return [
        Row(
            f"tf2 follow loop: turtle1's pose -> turtle2's cmd_vel, p50 / p99 ({steps} moves)",
            f"{fmt_ms(p50(loop))} / {fmt_ms(p99(loop))}",
            f"{fmt_ms(p50(phase))} / {fmt_ms(p99(phase))} (the listener's 1 s timer alone)",
            p50(loop) / p50(phase),
            "the next tick (ratio 1)",
            p50(loop) <= p50(phase) * 1.05,
        ),
        Row(
            "tf2 follow loop: turtle1's pose -> broadcaster's /tf, p50 / p99",
            f"{fmt_ms(p50(hop))} / {fmt_ms(p99(hop))}" if hop else "not seen",
            "",
        ),
    ]
