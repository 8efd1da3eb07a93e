"""rqt_console, rqt_logger_level, roslaunch-logs: the log lines, a node's level, the log folder."""

from __future__ import annotations

import re
import sys
import time
from pathlib import Path

import pytest
from helpers import NodeProcess

from ros2cmd.log import latest_launch_folder

BIN = Path(sys.executable).parent
LINE = re.compile(r"^\[(\d\d:\d\d:\d\d\.\d{3})\] \[(\w+)\] \[([\w.]+)\]: (.*)$")


def tool(node_process, *args: str) -> NodeProcess:
    return node_process(str(BIN / args[0]), *args[1:])


def finished(proc: NodeProcess) -> list[str]:
    assert proc.wait() == 0, proc.output
    assert "Traceback" not in proc.output
    return proc.lines


def heard(proc: NodeProcess, text: str) -> int:
    """The number N of the talker's last 'hello world N' line so far."""
    numbers = [int(m) for line in proc.lines for m in re.findall(rf"{text} (\d+)", line)]
    return max(numbers, default=-1)


@pytest.fixture
def talkers(node_process):
    """Two nodes logging INFO lines ten times a second: /talker and /topic_publisher."""
    talker = node_process("-m", "ros_tutorials_topic.talker")
    publisher = node_process("-m", "ros_tutorials_topic.publisher")
    talker.wait_for_output(lambda lines: any("hello world 3" in x for x in lines), what="talker")
    publisher.wait_for_output(lambda lines: any("send msg" in x for x in lines), what="publisher")
    return talker, publisher


def test_console_filters_by_node_and_text(node_process, talkers):
    lines = finished(tool(node_process, "rqt_console", "--node", "/talker", "-n", "5"))
    assert len(lines) == 5
    for line in lines:
        _time, level, logger, message = LINE.match(line).groups()
        assert (level, logger) == ("INFO", "talker") and message.startswith("hello world")
    lines = finished(tool(node_process, "rqt_console", "--text", "SEND MSG", "-n", "4"))
    assert len(lines) == 4
    assert all("[topic_publisher]: send msg = " in line for line in lines), lines
    # Not a terminal: no colour codes.
    assert not any("\033[" in line for line in lines)


def test_console_filters_by_level(node_process):
    server = node_process(
        "-m", "ros_tutorials_parameter.server", "--ros-args", "-p", "calculation_method:=4"
    )
    server.wait_for_output(lambda lines: any("ready srv server!" in x for x in lines))
    console = tool(node_process, "rqt_console", "--level", "warn", "-n", "1")
    # A warning logged before the console subscribed is not shown: call until it prints one.
    deadline = time.monotonic() + 60
    while console.process.poll() is None and time.monotonic() < deadline:
        call = NodeProcess(str(BIN / "rosservice"), "call", "/ros_tutorial_srv", "7", "0")
        assert call.wait() == 0, call.output
    lines = finished(console)
    assert len(lines) == 1
    assert re.search(r"\[WARN\] \[service_server\]: division by zero \(7 / 0\)", lines[0]), lines
    assert "request" not in lines[0]  # the INFO lines around it are filtered out


def test_console_since_includes_what_rosout_still_holds(node_process, talkers):
    talker, _ = talkers
    before = heard(talker, "hello world")
    lines = finished(
        tool(node_process, "rqt_console", "--node", "talker", "--since", "10", "-n", "1")
    )
    numbers = [int(m.group(1)) for m in map(re.compile(r"hello world (\d+)").search, lines) if m]
    assert numbers, lines
    assert numbers[0] <= before, lines  # logged before the console started


def _stamped(lines: list[str], text: str) -> list[float]:
    """The ROS log stamps of a node's output lines that contain text."""
    stamps = [re.search(r"\[(\d+\.\d+)\]", line) for line in lines if text in line]
    return [float(m.group(1)) for m in stamps if m]


def test_logger_level_change_takes_effect_in_the_nodes_output(node_process, talkers):
    # The topic lesson's publisher: the lesson node that serves the logger services.
    _, publisher = talkers
    node = "/topic_publisher"
    assert finished(tool(node_process, "rqt_logger_level", node))[-1].startswith(f"{node}: UNSET")
    lines = finished(tool(node_process, "rqt_logger_level", node, "warn"))
    assert lines[-1] == f"{node}: WARN"
    quiet_from = time.time()
    # While WARN, its INFO lines stop: watch for a second and a half of its life.
    publisher.wait_for_output(lambda lines: time.time() - quiet_from > 1.5, timeout=10)
    count = len(_stamped(publisher.lines, "send msg"))
    lines = finished(tool(node_process, "rqt_logger_level", node, "info"))
    assert lines[-1] == f"{node}: INFO"
    publisher.wait_for_output(
        lambda lines: len(_stamped(lines, "send msg")) > count + 3, what="INFO again"
    )
    silent = [
        t for t in _stamped(publisher.lines, "send msg") if quiet_from + 0.3 < t < quiet_from + 1.5
    ]
    assert not silent, f"INFO lines while the level was WARN: {silent}"


def test_logger_level_errors_are_one_clear_line(node_process, ros_domain):
    # A node without the logger services: the tool's own kind of node, a plain rclpy one.
    plain = node_process(
        "-c",
        "import rclpy; from ros_tutorials_common.dds import apply_dds_defaults; "
        "apply_dds_defaults(); rclpy.init(); n = rclpy.create_node('plain'); "
        "print('up', flush=True); rclpy.spin(n)",
    )
    plain.wait_for_output(lambda lines: "up" in lines)
    for args, message in (
        (("/plain", "warn"), "does not serve /plain/set_logger_levels"),
        (("/nobody", "--timeout", "1"), "unknown node '/nobody'"),
    ):
        proc = NodeProcess(str(BIN / "rqt_logger_level"), *args)
        assert proc.wait() == 1
        assert len(proc.lines) == 1 and message in proc.lines[0], proc.output
    bad = NodeProcess(str(BIN / "rqt_logger_level"), "/plain", "loud")
    assert bad.wait() == 2 and "invalid choice: 'loud'" in bad.output


def test_roslaunch_logs_prints_the_latest_launch_folder(node_process, tmp_path, monkeypatch):
    monkeypatch.setenv("ROS_LOG_DIR", str(tmp_path))
    missing = NodeProcess(str(BIN / "roslaunch-logs"), env={"ROS_LOG_DIR": str(tmp_path)})
    assert missing.wait() == 1 and missing.lines[0].startswith("error: no launch logs in")
    launcher = node_process("-m", "launcher", "union.launch", env={"ROS_LOG_DIR": str(tmp_path)})
    launcher.wait_for_output(lambda lines: any("logging to" in x for x in lines))
    logging_to = next(x for x in launcher.lines if "logging to" in x).split("logging to ")[1]
    proc = NodeProcess(str(BIN / "roslaunch-logs"), env={"ROS_LOG_DIR": str(tmp_path)})
    assert proc.wait() == 0
    assert proc.lines == [logging_to.strip()]
    assert latest_launch_folder() == Path(logging_to.strip())


def test_seed_004_sets_its_talkers_level_and_the_listing_names_who_cannot(node_process):
    """Seed 004's step 30: `rosrun my_package talker.py`, then rqt_logger_level. The talker
    serves the logger services; a node that does not (a plain rclpy node) is listed with why."""
    talker = node_process(str(BIN / "rosrun"), "my_package", "talker.py")
    talker.wait_for_output(lambda lines: any("hello world" in x for x in lines), what="talker")
    plain = node_process(
        "-c",
        "import rclpy; from ros_tutorials_common.dds import apply_dds_defaults; "
        "apply_dds_defaults(); rclpy.init(); n = rclpy.create_node('plain'); "
        "print('up', flush=True); rclpy.spin(n)",
    )
    plain.wait_for_output(lambda lines: "up" in lines)
    listed = "\n".join(finished(tool(node_process, "rqt_logger_level")))
    assert "/talker: UNSET (the default applies" in listed, listed
    assert (
        "/plain: cannot be set: it serves no /plain/get_logger_levels (created without "
        "enable_logger_service=True)" in listed
    ), listed
    assert finished(tool(node_process, "rqt_logger_level", "/talker", "warn"))[-1] == (
        "/talker: WARN"
    )
    quiet_from = time.time()
    talker.wait_for_output(lambda lines: time.time() - quiet_from > 1.5, timeout=10)
    silent = [t for t in _stamped(talker.lines, "hello world") if t > quiet_from + 0.3]
    assert not silent, f"INFO lines while the level was WARN: {silent}"
