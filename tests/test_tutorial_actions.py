"""The ROS 2 Jazzy tutorial "Understanding actions" (Beginner: CLI tools), typed as printed.

This project's turtlesim runs as a process (headless), turtle_teleop_key in a pseudo-terminal
(it holds the action's client); each `ros2 action ...` line of the page is typed as the page
prints it, and its output is compared with the page's, line by line. Goal IDs and the
measured angles differ from run to run: those are compared by their form and size.
"""

from __future__ import annotations

import re
import shlex

import pytest
from helpers import BIN, fails, run, spin_until
from rclpy.action import ActionClient
from rclpy.node import Node
from test_turtlesim_processes import HEADLESS, Terminal
from test_tutorial_parameters import TURTLESIM, page, shared_turtlesim  # noqa: F401
from turtlesim.action import RotateAbsolute

ROTATE = "ros2 action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute"
GOAL_ID = re.compile(r"Goal accepted with ID: [0-9a-f]{32}")


@pytest.fixture
def turtlesim(own_domain, node_process):  # the page: only what the test starts
    sim = node_process(*TURTLESIM, env=HEADLESS)
    sim.wait_for_text("Spawning turtle [turtle1]")
    return sim


@pytest.fixture
def teleop(ros_domain):
    terminal = Terminal()
    terminal.wait_for("'Q' to quit.")
    yield terminal
    terminal.close()


def result_delta(lines: list[str]) -> float:
    """The `delta` of the `Result:` block."""
    at = lines.index("Result:")
    name, value = lines[at + 1].split(": ")
    assert name == "    delta"
    return float(value)


@pytest.mark.long  # the page, step by step: 10 to 15 s
def test_the_actions_page(turtlesim, teleop):
    # 4 ros2 action list, -t; 5 ros2 action type; 6 ros2 action info
    assert page("ros2 action list") == "/turtle1/rotate_absolute\n"
    assert page("ros2 action list -t") == (
        "/turtle1/rotate_absolute [turtlesim/action/RotateAbsolute]\n"
    )
    assert page("ros2 action type /turtle1/rotate_absolute") == "turtlesim/action/RotateAbsolute\n"
    assert page("ros2 action info /turtle1/rotate_absolute").splitlines() == [
        "Action: /turtle1/rotate_absolute",
        "Action clients: 1",
        "    /teleop_turtle",
        "Action servers: 1",
        "    /turtlesim",
    ]

    # 8 ros2 action send_goal: the goal, its ID, the result, the status
    lines = page(f'{ROTATE} "{{theta: 1.57}}"').splitlines()
    assert lines[:4] == [
        "Waiting for an action server to become available...",
        "Sending goal:",
        "     theta: 1.57",
        "",
    ]
    assert GOAL_ID.fullmatch(lines[4]) and lines[5] == ""
    assert lines[6:] == ["Result:", lines[7], "", "Goal finished with status: SUCCEEDED"]
    # each end within turtlesim's tolerance (0.02 rad) of its goal
    assert result_delta(lines) == pytest.approx(-1.57, abs=0.05)  # from heading 0
    turtlesim.wait_for_text("Rotation goal completed successfully")

    # ... and with --feedback: the remaining angle, block after block, to the other side
    lines = page(f'{ROTATE} "{{theta: -1.57}}" --feedback').splitlines()
    assert lines[1:4] == ["Sending goal:", "     theta: -1.57", ""]
    assert GOAL_ID.fullmatch(lines[4])
    feedback = [
        float(lines[at + 1].removeprefix("    remaining: "))
        for at, line in enumerate(lines)
        if line == "Feedback:"
    ]
    assert len(feedback) >= 2
    assert all(lines[at + 2] == "" for at, line in enumerate(lines) if line == "Feedback:")
    assert -3.15 < feedback[0] < feedback[-1] <= 0  # the page's -3.1268..., -3.1108..., ...
    assert result_delta(lines) == pytest.approx(3.14, abs=0.05)
    assert lines[-1] == "Goal finished with status: SUCCEEDED"


def test_ctrl_c_cancels_the_goal(turtlesim, node_process):
    words = shlex.split(f'{ROTATE} "{{theta: 3.0}}" --feedback')
    goal = node_process(str(BIN / words[0]), *words[1:])
    goal.wait_for_text("Feedback:")
    assert goal.interrupt() == 130
    lines = goal.output.splitlines()
    assert lines[-1] == "Goal canceled."
    # Feedback that comes while the cancel request is answered is printed, as ros2action
    # does (it spins the node until the answer); nothing else comes between.
    between = lines[lines.index("Canceling goal...") + 1 : -1]
    assert all(line in ("", "Feedback:") or line.startswith("  ") for line in between), between
    assert "Traceback" not in goal.output
    turtlesim.wait_for_text("Rotation goal canceled")


def test_a_goal_the_server_aborts_ends_with_its_status_and_exit_1(
    turtlesim, node_process, executor
):
    """The page's D then G: a new goal aborts the one running (here sent by the test itself,
    at once, while the first has 3 s to go)."""
    words = shlex.split(f'{ROTATE} "{{theta: 3.0}}" --feedback')
    first = node_process(str(BIN / words[0]), *words[1:])
    first.wait_for_text("Feedback:")
    node = Node("second_client", context=executor.context)
    executor.add_node(node)
    client = ActionClient(node, RotateAbsolute, "/turtle1/rotate_absolute")
    try:
        spin_until(executor, client.server_is_ready, what="the action server")
        sent = client.send_goal_async(RotateAbsolute.Goal(theta=0.0))
        spin_until(executor, sent.done, what="the second goal accepted")
        assert first.wait() == 1
    finally:
        client.destroy()  # destroy_node leaves an action client (and so its node) alive
    assert first.output.splitlines()[-2:] == [
        "Goal finished with status: ABORTED",
        "error: the goal did not succeed: ABORTED",
    ]
    turtlesim.wait_for_text("Rotation goal received before a previous goal finished")


def test_info_and_list_options(turtlesim):  # counts: turtlesim alone in its domain
    assert page("ros2 action info /turtle1/rotate_absolute -t -c").splitlines() == [
        "Action: /turtle1/rotate_absolute",
        "Action clients: 0",
        "Action servers: 1",
    ]
    assert page("ros2 action info turtle1/rotate_absolute --show-types").splitlines()[-1] == (
        "    /turtlesim [turtlesim/action/RotateAbsolute]"
    )
    assert page("ros2 action list -c") == "1\n"
    stdin = run(*shlex.split(f"{ROTATE} --stdin"), input="theta: 0.0\n")
    assert stdin.returncode == 0, stdin.stderr
    assert "     theta: 0.0" in stdin.stdout.splitlines()


class TestAgainstOneTurtlesim:
    """Commands that leave turtlesim as it is: one turtlesim for them all."""

    @pytest.mark.parametrize(
        "line,expected",
        [
            (
                "ros2 action info /nope --timeout 1",
                "error: unknown action '/nope': no server or client seen (waited 1 s)",
            ),
            (
                "ros2 action type /nope --timeout 1",
                "error: unknown action '/nope': not seen in the graph (waited 1 s)",
            ),
            (
                "ros2 action send_goal /nope turtlesim/action/RotateAbsolute '{}' --timeout 1",
                "error: no action server for '/nope' (waited 1 s)",
            ),
            (
                "ros2 action send_goal /turtle1/rotate_absolute "
                "ros_tutorials_interfaces/action/Fibonacci '{order: 5}'",
                "error: action '/turtle1/rotate_absolute' has type "
                "turtlesim/action/RotateAbsolute, not ros_tutorials_interfaces/action/Fibonacci",
            ),
            (f'{ROTATE} "{{theta: .nan}}"', "Goal was rejected."),  # turtlesim refuses it
            (f'{ROTATE} "{{heading: 1}}"', "error: 'heading' is not a field of "),
            (f'{ROTATE} "{{theta: one}}"', "error: theta is a number (float), got 'one'"),
            (f'{ROTATE} "{{theta: 1"', "error: invalid YAML"),
            (
                "ros2 action send_goal /turtle1/rotate_absolute turtlesim/action/Nope '{}'",
                "error: unknown action type 'turtlesim/action/Nope'",
            ),
        ],
    )
    def test_bad_input_is_one_line(self, shared_turtlesim, line, expected):  # noqa: F811
        assert fails(*shlex.split(line)).startswith(expected)


def test_usage_is_exit_2():
    result = run("ros2", "action", "send_goal", "/turtle1/rotate_absolute")
    assert result.returncode == 2
    assert "the following arguments are required: action_type" in result.stderr
