"""tf2_ros's commands as a learner types them (`ros2 run tf2_ros ...`), as processes: tf2_echo
prints a static_transform_publisher's frame as the pages show it, both argument styles of
static_transform_publisher, tf2_monitor's report, and bad arguments answered as the C++ tools
do (one line, their exit status). Also: `ros2 pkg executables tf2_ros`, and a launch file's
Node(package='tf2_ros', executable='static_transform_publisher') found by the package index."""

from __future__ import annotations

import math
import os
import subprocess
import sys

import pytest
from geometry_msgs.msg import TransformStamped
from helpers import BIN, TIMEOUT, ok, run

from ros_tutorials_common import packages
from tf2_ros.static_transform_publisher import ArgumentError, parse
from tf2_ros.tf2_echo import format_transform

ROS2 = str(BIN / "ros2")


def test_tf2_echo_prints_what_the_introduction_page_shows():
    message = TransformStamped()
    message.header.stamp.sec, message.header.stamp.nanosec = 1683385338, 841997774
    t, r = message.transform.translation, message.transform.rotation
    t.x, t.y = 1.256, 0.216
    yaw = math.radians(-1.839)
    r.z, r.w = math.sin(yaw / 2), math.cos(yaw / 2)
    assert format_transform(message).splitlines() == [
        "At time 1683385338.841997774",
        "- Translation: [1.256, 0.216, 0.000]",
        "- Rotation: in Quaternion [0.000, 0.000, -0.016, 1.000]",
        "- Rotation: in RPY (radian) [0.000, 0.000, -0.032]",
        "- Rotation: in RPY (degree) [0.000, 0.000, -1.839]",
        "- Matrix:",
        "  0.999  0.032  0.000  1.256",
        " -0.032  0.999 -0.000  0.216",
        " -0.000  0.000  1.000  0.000",
        "  0.000  0.000  0.000  1.000",
    ]


def test_static_transform_publisher_reads_both_argument_styles(capfd):
    _, new = parse(["--x", "1", "--y", "2", "--yaw", "0.5", "--frame-id", "a",
                    "--child-frame-id", "b"])  # fmt: skip
    assert (new.header.frame_id, new.child_frame_id) == ("a", "b")
    assert new.transform.translation.y == 2.0
    assert new.transform.rotation.z == pytest.approx(math.sin(0.25))
    _, old = parse(["1", "2", "0", "0.5", "0", "0", "a", "b"])  # x y z yaw pitch roll
    assert old.transform == new.transform
    _, quaternion = parse(["0", "0", "1", "0", "0", "0", "1", "world", "mystaticturtle"])
    assert quaternion.transform.translation.z == 1.0 and quaternion.transform.rotation.w == 1.0
    assert (
        capfd.readouterr().err.count(
            "Old-style arguments are deprecated; see --help for new-style arguments"
        )
        == 2
    )
    for args, reason in [
        (["--x"], "Not enough arguments for --x"),
        (["--x", "one", "--frame-id", "a", "--child-frame-id", "b"],
         "Failed to parse --x argument as float"),
        (["--yaw", "1", "--qw", "1", "--frame-id", "a", "--child-frame-id", "b"],
         "Cannot specify both quaternion and Euler rotations"),
        (["--x", "1", "0", "0", "0", "0", "0", "0", "a", "b"],
         "Cannot specify both new-style (flags) and old-style (arguments)"),
        (["extra", "--frame-id", "a", "--child-frame-id", "b"],
         "Extra unparsed arguments on command-line"),
        (["--child-frame-id", "b"], "Frame id must not be empty"),
        (["--frame-id", "a"], "Child frame id must not be empty"),
    ]:  # fmt: skip
        with pytest.raises(ArgumentError) as error:
            parse(args)
        assert str(error.value) == reason


def test_tf2_echo_prints_the_frame_of_a_static_transform_publisher(node_process):
    publisher = node_process(ROS2, "run", "tf2_ros", "static_transform_publisher", "--x", "1",
                             "--y", "2", "--yaw", "0.5", "--frame-id", "world",
                             "--child-frame-id", "mystatic")  # fmt: skip
    publisher.wait_for_text("Spinning until stopped - publishing transform")
    publisher.wait_for_text("from 'world' to 'mystatic'")
    echo = node_process(ROS2, "run", "tf2_ros", "tf2_echo", "world", "mystatic")
    echo.wait_for_text("- Translation: [1.000, 2.000, 0.000]")
    lines = echo.lines[echo.lines.index("- Translation: [1.000, 2.000, 0.000]") - 1 :]
    assert lines[:6] == [
        "At time 0.0",  # a static transform: the latest common time is 0
        "- Translation: [1.000, 2.000, 0.000]",
        "- Rotation: in Quaternion [0.000, 0.000, 0.247, 0.969]",
        "- Rotation: in RPY (radian) [0.000, -0.000, 0.500]",
        "- Rotation: in RPY (degree) [0.000, -0.000, 28.648]",
        "- Matrix:",
    ]
    assert echo.interrupt() == 0
    assert publisher.interrupt() == 0
    assert "Traceback" not in echo.output + publisher.output


def test_tf2_echo_waits_for_frames_that_are_not_there(node_process):
    echo = node_process(ROS2, "run", "tf2_ros", "tf2_echo", "world", "turtle9", "5")
    echo.wait_for_text(
        'Waiting for transform world ->  turtle9: Invalid frame ID "world" passed to '
        "canTransform argument target_frame - frame does not exist"
    )
    assert echo.interrupt() == 0


def test_tf2_monitor_reports_the_frames_it_sees(node_process):
    publisher = node_process(ROS2, "run", "tf2_ros", "static_transform_publisher",
                             "--frame-id", "world", "--child-frame-id", "watched")  # fmt: skip
    publisher.wait_for_text("from 'world' to 'watched'")
    monitor = node_process(ROS2, "run", "tf2_ros", "tf2_monitor")
    monitor.wait_for_text("Gathering data on all frames for 10 seconds...")
    monitor.wait_for_text("RESULTS: for all Frames", timeout=60)
    monitor.wait_for_text("All Broadcasters:")
    monitor.wait_for_output(
        lambda lines: any(
            line.startswith("Frame: watched, published by <no authority available>, Average Delay:")
            for line in lines
        ),
        what="the watched frame's delays",
    )
    monitor.wait_for_text("Node: <no authority available> ")
    assert monitor.interrupt() == 0


@pytest.mark.parametrize(
    ("args", "status", "line"),
    [
        (["tf2_echo", "a", "b", "fast"], 2,
         "Failed to convert rate argument 'fast' to a floating-point number"),
        (["tf2_echo", "a", "b", "1.0x"], 3,
         "Failed to convert rate argument '1.0x' to a floating-point number"),
        (["tf2_echo", "a", "b", "0"], 2, "The echo rate '0' must be a number greater than 0"),
        (["static_transform_publisher", "--frame-id", "a"], 1,
         "error parsing command line arguments: Child frame id must not be empty"),
        (["tf2_monitor", "only_one"], 255, "TF_Monitor: usage: tf2_monitor framea frameb"),
    ],
)  # fmt: skip
def test_bad_arguments_give_one_line_and_the_tools_status(args, status, line):
    result = run("ros2", "run", "tf2_ros", *args)
    assert result.returncode == status
    errors = result.stderr.strip().splitlines()
    assert len(errors) == 1 and errors[0].endswith(line), result.stderr
    assert "Traceback" not in result.stderr


def test_tf2_echo_without_frames_prints_its_usage():
    result = run("ros2", "run", "tf2_ros", "tf2_echo")
    assert result.returncode == 1
    assert result.stdout.startswith("Usage: tf2_echo source_frame target_frame [echo_rate]\n")


def test_the_commands_are_the_packages_executables():
    assert ok("ros2", "pkg", "executables", "tf2_ros").splitlines() == [
        "tf2_ros static_transform_publisher",
        "tf2_ros tf2_echo",
        "tf2_ros tf2_monitor",
    ]
    # What a launch file's Node(package='tf2_ros', executable=...) and rosrun start.
    assert packages.command("tf2_ros", "static_transform_publisher") == [
        sys.executable,
        "-m",
        "tf2_ros.static_transform_publisher",
    ]
    assert packages.executable_commands("tf2_py") == {}  # a library: nothing to run


# The tool's first node is made right as Ctrl-C comes: rclpy's handler shuts ROS down and the
# KeyboardInterrupt is raised there ("raised"), or it is lost in code C called and rcl then
# refuses the node in the shut-down context ("lost"). The signal is real; rclpy is untouched
# but for the moment it comes.
CTRL_C_AS_THE_NODE_IS_MADE = """
import os, runpy, signal, sys
import rclpy.node
original = rclpy.node.Node.__init__
def first_node(self, *args, **kwargs):
    rclpy.node.Node.__init__ = original
    try:
        signal.raise_signal(signal.SIGINT)
    except KeyboardInterrupt:
        if os.environ["CTRL_C"] == "raised":
            raise
    original(self, *args, **kwargs)
rclpy.node.Node.__init__ = first_node
module = sys.argv.pop(1)
runpy.run_module(module, run_name="__main__", alter_sys=True)
"""


@pytest.mark.parametrize("how", ["raised", "lost"])
@pytest.mark.parametrize(
    ("module", "args", "status"),
    [
        ("tf2_ros.tf2_echo", ["world", "turtle1"], 0),
        ("tf2_ros.tf2_monitor", [], 0),
        ("tf2_ros.static_transform_publisher", ["--frame-id", "a", "--child-frame-id", "b"], 0),
        ("tf2_tools.view_frames", ["-o", "never_written"], 130),
    ],
)
def test_ctrl_c_as_a_tool_makes_its_node_ends_it_with_no_traceback(
    module, args, status, how, ros_domain, tmp_path
):
    result = subprocess.run(
        [sys.executable, "-c", CTRL_C_AS_THE_NODE_IS_MADE, module, *args],
        capture_output=True, text=True, timeout=TIMEOUT, cwd=tmp_path,
        env={**os.environ, "CTRL_C": how},
    )  # fmt: skip
    assert "Traceback" not in result.stderr, result.stderr
    assert result.returncode == status, result.stderr
    assert not list(tmp_path.iterdir())  # view_frames stopped before it wrote anything


def test_tf2_echo_ends_quietly_when_its_reader_has_gone(ros_domain):
    # `ros2 run tf2_ros tf2_echo a a 10 | head -1`: one frame is its own transform at once.
    echo = subprocess.Popen(
        [ROS2, "run", "tf2_ros", "tf2_echo", "a", "a", "10"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )  # fmt: skip
    try:
        assert echo.stdout.readline() == "At time 0.0\n"
        echo.stdout.close()
        _, errors = echo.communicate(timeout=TIMEOUT)
    finally:
        echo.kill()
    assert "Traceback" not in errors, errors
    assert echo.returncode == 0, errors


def test_sigterm_ends_tf2_echo_at_once_whatever_its_rate(ros_domain):
    # One echo every 1000 s: SIGTERM must not wait for the next.
    echo = subprocess.Popen(
        [ROS2, "run", "tf2_ros", "tf2_echo", "a", "a", "0.001"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )  # fmt: skip
    try:
        assert echo.stdout.readline() == "At time 0.0\n"
        echo.terminate()
        _, errors = echo.communicate(timeout=TIMEOUT)
    finally:
        echo.kill()
    assert "Traceback" not in errors, errors
    assert echo.returncode == 0, errors


# A Ctrl-C whose KeyboardInterrupt is lost before rclpy installs its handler (raised in code
# whose errors C drops): the press is counted, and view_frames must not listen on regardless.
LOST_BEFORE_RCLPY_INIT = """
import runpy, signal, sys
import rclpy
original = rclpy.init
def init(*args, **kwargs):
    try:
        signal.raise_signal(signal.SIGINT)
    except KeyboardInterrupt:
        pass
    original(*args, **kwargs)
rclpy.init = init
runpy.run_module("tf2_tools.view_frames", run_name="__main__", alter_sys=True)
"""


def test_view_frames_stops_on_a_ctrl_c_lost_before_ros_started(ros_domain, tmp_path):
    result = subprocess.run(
        [sys.executable, "-c", LOST_BEFORE_RCLPY_INIT, "-t", "1000", "-o", "never_written"],
        capture_output=True, text=True, timeout=TIMEOUT, cwd=tmp_path,
    )  # fmt: skip
    assert result.returncode == 130, result.stderr
    assert "Traceback" not in result.stderr, result.stderr
    assert not list(tmp_path.iterdir())
