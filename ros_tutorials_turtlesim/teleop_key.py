"""turtle_teleop_key: drive turtle1 with the keyboard (the seeds' first demo).

    turtlesim_node          # terminal 1
    turtle_teleop_key       # terminal 2: arrow keys drive, q quits

Node ``teleop_turtle`` publishes one geometry_msgs/msg/Twist on ``turtle1/cmd_vel`` per arrow
key (up/down: linear.x = +/-scale_linear, left/right: angular.z = +/-scale_angular; both
parameters default to 2.0). The letters around F send ``turtle1/rotate_absolute`` goals (G east,
T, R north, E, D west, C, V south, B), F cancels the goal, Q quits.

The terminal is put into single-key mode while it runs and restored on every way out: q, Ctrl-C,
a closed stdin, an error. Without a terminal on stdin (a pipe, a launch file) it says so and
exits with status 1.
"""

from __future__ import annotations

import contextlib
import os
import select
import signal
import sys
import termios
import threading
import tty

import rclpy
from geometry_msgs.msg import Twist
from rclpy.action import ActionClient
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from turtlesim.action import RotateAbsolute

from ros_tutorials_common.ros import SpinThread, init
from ros_tutorials_common.shutdown import program_main

HELP = """Reading from keyboard
---------------------------
Use arrow keys to move the turtle.
Use G|B|V|C|D|E|R|T keys to rotate to absolute orientations. 'F' to cancel a rotation.
'Q' to quit."""

ARROWS = {
    "A": (1.0, 0.0),
    "B": (-1.0, 0.0),
    "C": (0.0, -1.0),
    "D": (0.0, 1.0),
}  # up down right left
ROTATE_ACTION = "turtle1/rotate_absolute"
HEADINGS = {
    "g": 0.0,
    "t": 0.7854,
    "r": 1.5708,
    "e": 2.3562,
    "d": 3.1416,
    "c": -2.3562,
    "v": -1.5708,
    "b": -0.7854,
}


class TeleopTurtle(Node):
    def __init__(self, **kwargs) -> None:
        super().__init__("teleop_turtle", enable_logger_service=True, **kwargs)
        self.declare_parameter("scale_angular", 2.0)
        self.declare_parameter("scale_linear", 2.0)
        qos = QoSProfile(depth=7, reliability=ReliabilityPolicy.RELIABLE)  # turtlesim's
        self.twist_publisher = self.create_publisher(Twist, "turtle1/cmd_vel", qos)
        self.rotate_client = ActionClient(self, RotateAbsolute, ROTATE_ACTION)
        self.goal_future = None  # the latest goal sent, until the server answers
        self.goal_handle = None  # ... and its handle once it has
        self.cancel_wanted = False  # F pressed before the server had answered
        self.goal_lock = threading.Lock()  # keys come from the main thread, answers from ROS's

    def drive(self, linear: float, angular: float) -> None:
        twist = Twist()
        twist.linear.x = self.get_parameter("scale_linear").value * linear
        twist.angular.z = self.get_parameter("scale_angular").value * angular
        self.twist_publisher.publish(twist)

    def send_goal(self, theta: float) -> None:
        if not self.rotate_client.server_is_ready():
            self.get_logger().warning(f"{ROTATE_ACTION} is not available: is turtlesim running?")
            return
        with self.goal_lock:
            self.cancel_wanted = False
            self.goal_future = self.rotate_client.send_goal_async(RotateAbsolute.Goal(theta=theta))
        self.goal_future.add_done_callback(self.on_goal_response)

    def on_goal_response(self, future) -> None:
        with self.goal_lock:
            if future is not self.goal_future:  # an older goal's answer
                return
            self.goal_handle = future.result()
            if self.cancel_wanted and self.goal_handle.accepted:
                self.goal_handle.cancel_goal_async()

    def cancel_goal(self) -> None:
        with self.goal_lock:
            if self.goal_future is not None and not self.goal_future.done():
                self.cancel_wanted = True  # cancelled as soon as the server answers
            elif self.goal_handle is not None:
                self.goal_handle.cancel_goal_async()


class Keyboard:
    """Single key presses from the terminal on stdin; arrows come as ESC [ A..D."""

    def __init__(self, fd: int) -> None:
        self.fd = fd
        self.pending = b""

    def read_key(self, timeout: float = 0.1) -> str | None:
        """The next key: 'up'.. as arrow letters 'A'..'D' prefixed by ESC, or a character.

        Returns '' when nothing was typed within timeout; None when stdin is closed.
        """
        if not self.pending:
            ready, _, _ = select.select([self.fd], [], [], timeout)
            if not ready:
                return ""
            try:
                data = os.read(self.fd, 32)
            except OSError:  # the terminal went away (EIO)
                data = b""
            if not data:
                return None
            self.pending = data
        if self.pending[:1] == b"\x1b" and self.pending[1:2] in (b"[", b"O"):
            if len(self.pending) < 3:  # the rest of the arrow's sequence is still coming
                ready, _, _ = select.select([self.fd], [], [], 0.05)
                if ready:
                    self.pending += os.read(self.fd, 32)
            key, self.pending = "\x1b" + chr(self.pending[2]) if len(self.pending) > 2 else "", b""
            return key
        key, self.pending = chr(self.pending[0]), self.pending[1:]
        return key


def key_loop(node: TeleopTurtle, keyboard: Keyboard) -> None:
    print(HELP, flush=True)
    while True:
        key = keyboard.read_key()
        if key is None or key.lower() == "q":  # stdin closed, or q
            return
        if key.startswith("\x1b") and key[1:] in ARROWS:
            node.drive(*ARROWS[key[1:]])
        elif key.lower() in HEADINGS:
            node.send_goal(HEADINGS[key.lower()])
        elif key.lower() == "f":
            node.cancel_goal()


def _hang_up(_signum: int, _frame) -> None:
    raise KeyboardInterrupt  # the terminal was closed: leave as on Ctrl-C, cleaning up


@program_main
def main(argv: list[str] | None = None) -> int:
    fd = sys.stdin.fileno()
    if not os.isatty(fd):
        print(
            "turtle_teleop_key reads single key presses, but its stdin is not a terminal "
            "(a pipe, a file or a launch file): run it in a terminal of its own",
            file=sys.stderr,
        )
        return 1
    init(argv)  # rclpy.init with this project's DDS defaults
    signal.signal(signal.SIGHUP, _hang_up)
    node = TeleopTurtle()
    spinner = SpinThread(node, name="ros")  # ROS alongside the key loop
    saved = termios.tcgetattr(fd)
    try:
        tty.setcbreak(fd)  # keys arrive one by one, not echoed; Ctrl-C still interrupts
        key_loop(node, Keyboard(fd))
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        with contextlib.suppress(termios.error):  # unless the terminal itself is gone
            termios.tcsetattr(fd, termios.TCSADRAIN, saved)
        # Stop the background spin and wait for it: a thread still inside rclpy's C++ code
        # when Python exits aborts the process.
        spinner.stop()
        node.destroy_node()
        rclpy.try_shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
