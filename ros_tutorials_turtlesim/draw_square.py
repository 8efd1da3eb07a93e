"""draw_square: the ROS 2 turtlesim tutorial that drives turtle1 around a square.

    turtlesim_node      # terminal 1
    draw_square         # terminal 2

Node ``draw_square`` first calls ``reset`` (a clean canvas, turtle1 back in the middle), then
steers by the pose it reads on ``turtle1/pose``: forward 2 m at 1 m/s, stop, turn a quarter
at 0.4 rad/s, stop, and again, logging each goal ("New goal [x y, theta]") and "Reached goal".
"""

from __future__ import annotations

import math
import sys

from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from std_srvs.srv import Empty
from turtlesim.msg import Pose

from ros_tutorials_common.ros import run_node
from ros_tutorials_common.shutdown import program_main

SIDE = 2.0  # m
FORWARD, STOP_FORWARD, TURN, STOP_TURN = "forward", "stop_forward", "turn", "stop_turn"


class DrawSquare(Node):
    def __init__(self, **kwargs) -> None:
        super().__init__("draw_square", enable_logger_service=True, **kwargs)
        qos = QoSProfile(depth=7, reliability=ReliabilityPolicy.RELIABLE)  # turtlesim's
        self.twist_publisher = self.create_publisher(Twist, "turtle1/cmd_vel", qos)
        self.create_subscription(Pose, "turtle1/pose", self.on_pose, qos)
        self.reset_client = self.create_client(Empty, "reset")
        self.pose: Pose | None = None
        self.goal: Pose | None = None
        self.state = FORWARD
        self.reset_done = None  # the future of the reset call, once the service is there
        self.create_timer(0.016, self.on_timer)

    def on_pose(self, pose: Pose) -> None:
        self.pose = pose

    def command(self, linear: float, angular: float) -> None:
        twist = Twist()
        twist.linear.x = linear
        twist.angular.z = angular
        self.twist_publisher.publish(twist)

    def reached_goal(self) -> bool:
        return (
            abs(self.pose.x - self.goal.x) < 0.1
            and abs(self.pose.y - self.goal.y) < 0.1
            and abs(self.pose.theta - self.goal.theta) < 0.01
        )

    def stopped(self) -> bool:
        return self.pose.angular_velocity < 0.0001 and self.pose.linear_velocity < 0.0001

    def set_goal(self, x: float, y: float, theta: float) -> None:
        self.goal = Pose(x=x, y=y, theta=theta)
        self.get_logger().info(f"New goal [{self.goal.x:f} {self.goal.y:f}, {self.goal.theta:f}]")

    def goal_ahead(self) -> None:
        pose = self.pose
        self.set_goal(
            math.cos(pose.theta) * SIDE + pose.x, math.sin(pose.theta) * SIDE + pose.y, pose.theta
        )

    def on_timer(self) -> None:
        # Reset the simulator first, and wait until it has answered.
        if self.reset_done is None:
            if self.reset_client.service_is_ready():
                self.reset_done = self.reset_client.call_async(Empty.Request())
                self.pose = None  # a pose from before the reset is stale
            return
        if not self.reset_done.done() or self.pose is None:
            return
        if self.goal is None:
            self.state = FORWARD
            self.goal_ahead()

        if self.state == FORWARD:
            if self.reached_goal():
                self.state = STOP_FORWARD
                self.command(0.0, 0.0)
            else:
                self.command(1.0, 0.0)
        elif self.state == STOP_FORWARD:
            if self.stopped():
                self.get_logger().info("Reached goal")
                self.state = TURN
                theta = math.fmod(self.pose.theta + math.pi / 2, 2 * math.pi)
                if theta >= math.pi:  # wrap to [-pi, pi)
                    theta -= 2 * math.pi
                self.set_goal(self.pose.x, self.pose.y, theta)
            else:
                self.command(0.0, 0.0)
        elif self.state == TURN:
            if self.reached_goal():
                self.state = STOP_TURN
                self.command(0.0, 0.0)
            else:
                self.command(0.0, 0.4)
        elif self.state == STOP_TURN:
            if self.stopped():
                self.get_logger().info("Reached goal")
                self.state = FORWARD
                self.goal_ahead()
            else:
                self.command(0.0, 0.0)


@program_main
def main(argv: list[str] | None = None) -> int:
    return run_node(DrawSquare, argv)  # rclpy.init with the DDS defaults, spin until Ctrl-C


if __name__ == "__main__":
    sys.exit(main())
