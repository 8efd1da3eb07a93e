"""The tools under bad input: one clear line and a non-zero exit, never a traceback, never
unbounded memory (rosparam load /dev/zero, a YAML alias bomb on the command line)."""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import threading
import time
from pathlib import Path

import pytest
from helpers import TIMEOUT
from test_launcher_bad_input import BOMB
from test_ros2 import BIN, fails, ok, tool


class TestAgainstOneParameterServer:
    """Refused requests to one parameter server, which the tests share: none changes it."""

    def test_rosparam_set_an_integer_beyond_int64_is_one_line(self, unchanged_parameter_lesson):
        line = fails("rosparam", "set", "/calculation_method", "99999999999999999999")
        assert "does not fit a ROS integer (int64)" in line
        assert ok("rosparam", "get", "/calculation_method").strip() == "1"  # nothing changed

    def test_ros2cli_param_set_an_integer_beyond_int64_is_one_line(
        self, unchanged_parameter_lesson
    ):
        line = fails(
            "ros2",
            "param",
            "set",
            "/service_server",
            "calculation_method",
            "-99999999999999999999",
        )
        assert "does not fit a ROS integer (int64)" in line

    def test_the_tools_still_work_after_refusing(self, unchanged_parameter_lesson):
        """Nothing already running is hurt by a refused request."""
        fails("rosparam", "set", "/calculation_method", "99999999999999999999")
        result = tool("rosservice", "call", "/ros_tutorial_srv", "10", "5")
        assert result.returncode == 0 and "result: 15" in result.stdout


def test_a_number_into_a_string_field_is_refused():
    line = fails("rostopic", "pub", "-1", "/chatter", "std_msgs/String", "{data: 5}")
    assert "data is a string, got 5 (int)" in line and "quote it" in line
    line = fails("ros2", "topic", "pub", "/chatter", "std_msgs/msg/String", "{data: true}")
    assert "data is a string" in line


def test_text_that_is_not_unicode_is_refused_naming_the_field(context, executor):
    """YAML's "\\ud800" is half of a UTF-16 surrogate pair, which no UTF-8 string can hold:
    one line naming the field, from pub with a subscriber present and from a service call
    (send_goal fills its goal with the same code; no action here has a text field)."""
    from rclpy.node import Node
    from std_msgs.msg import String
    from turtlesim.srv import Spawn

    node = Node("surrogate_check", context=context)
    executor.add_node(node)
    node.create_subscription(String, "/surrogates", lambda _message: None, 10)
    called = []
    node.create_service(Spawn, "/surrogate_spawn", lambda request, response: called.append(1))
    expected = "is not valid Unicode text: '\\ud800' at position 1 is half of a UTF-16 surrogate"
    line = fails(
        "ros2", "topic", "pub", "--once", "/surrogates", "std_msgs/msg/String", '{data: "a\\ud800"}'
    )
    assert line == f"error: data {expected} pair"
    line = fails("rostopic", "pub", "-1", "/surrogates", "std_msgs/String", '{data: "a\\ud800"}')
    assert line == f"error: data {expected} pair"
    line = fails(
        "ros2", "service", "call", "/surrogate_spawn", "turtlesim/srv/Spawn", '{name: "a\\ud800"}'
    )
    assert line == f"error: name {expected} pair"
    assert called == []


def test_a_yaml_alias_bomb_on_the_command_line_is_refused():
    # Anchors inside the value: without the limit the error message alone (repr of 9**9
    # strings) would fill the memory.
    levels = ["&a [lol, lol, lol, lol, lol, lol, lol, lol, lol]"] + [
        f"&{name} [{', '.join([f'*{prev}'] * 9)}]"
        for prev, name in zip("abcdefgh", "bcdefghi", strict=True)
    ]
    bomb = f"{{data: [{', '.join(levels)}]}}"
    assert len(bomb) < 600
    line = fails("rostopic", "pub", "-1", "/chatter", "std_msgs/String", bomb)
    assert "once its aliases are expanded" in line
    line = fails("ros2", "topic", "pub", "/chatter", "std_msgs/msg/String", BOMB)
    assert "once its aliases are expanded" in line


def test_rosparam_load_dev_zero_is_refused_within_the_size_limit():
    line = fails("rosparam", "load", "/dev/zero")
    assert line == "error: /dev/zero is larger than 1 MiB; refusing to read it"
    line = fails("ros2", "param", "load", "/service_server", "/dev/zero")
    assert "larger than 1 MiB" in line


def test_ros2_param_set_sends_an_unquoted_date_as_its_text():
    """As upstream's ros2 param set (rclpy's get_parameter_value): what is not a bool, a number
    or a list of one of those is the text typed (a params file's date is refused, below)."""
    from rcl_interfaces.msg import ParameterType

    from ros2cmd.param.verb.set import typed_value

    value = typed_value("when", "2024-01-01")
    assert (value.type, value.string_value) == (ParameterType.PARAMETER_STRING, "2024-01-01")


@pytest.mark.parametrize(
    ("content", "expected"),
    [
        (b"/service_server:\n  ros__parameters:\n    calculation_method: 2024-01-01\n", "date"),
        (b"/service_server:\n  ros__parameters:\n    1: 2\n", "is not a string"),
        (b"/service_server:\n  ros__parameters:\n    x: 99999999999999999999\n", "int64"),
        (b"/service_server:\n  ros__parameters:\n    x: caf\xe9\n", "not UTF-8"),
    ],
)
def test_rosparam_load_checks_the_file_before_touching_a_node(tmp_path, content, expected):
    path = tmp_path / "params.yaml"
    path.write_bytes(content)
    assert expected in fails("rosparam", "load", str(path))


def test_rossrv_show_reading_dev_zero_is_refused():
    with open("/dev/zero", "rb") as zeros:
        done = subprocess.run(
            [str(BIN / "rossrv"), "show"], stdin=zeros, capture_output=True, timeout=TIMEOUT
        )
    assert done.returncode == 1 and b"Traceback" not in done.stderr
    assert b"longer than 4096 characters" in done.stderr


def test_rostopic_pub_at_1e9_hz_ends_cleanly_on_sigterm():
    """At -r 1e9 the loop never waits, so SIGTERM shuts ROS down between two publishes."""
    flood = ("pub", "-v", "-r", "1e9", "/hardening_flood", "std_msgs/String", "hi")  # -v: lines
    proc = subprocess.Popen(
        [str(BIN / "rostopic"), *flood],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    flooding = threading.Event()

    def drain() -> None:  # read the flood to its end, so the tool never sees a broken pipe
        assert proc.stdout is not None
        for line in proc.stdout:
            if line.startswith(b"publishing #100:"):
                flooding.set()

    reader = threading.Thread(target=drain, daemon=True)
    reader.start()
    try:
        assert flooding.wait(TIMEOUT), "rostopic pub -r 1e9 did not start publishing"
        proc.send_signal(signal.SIGTERM)
        assert proc.stderr is not None
        err = proc.stderr.read()
        proc.wait(TIMEOUT)
        reader.join(TIMEOUT)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    assert b"Traceback" not in err and b"RCLError" not in err, err.decode(errors="replace")
    assert proc.returncode == 0, err  # like Ctrl-C: how a flood ends


def _fifo(tmp_path) -> str:
    path = tmp_path / "params.fifo"
    os.mkfifo(path)
    return str(path)


def test_a_named_pipe_nobody_writes_to_is_refused_after_a_wait(tmp_path):
    """open() of a FIFO with no writer blocked for good; /proc/kmsg's read blocks though
    poll() says it has data. Both: one line after the wait, nothing left blocking."""
    from ros_tutorials_common import bounded

    fifo = _fifo(tmp_path)
    with pytest.raises(bounded.InputError, match=r"nothing came from it in 0\.5 s"):
        bounded.read_bytes(fifo, wait=0.5)
    if os.access("/proc/kmsg", os.R_OK):
        with pytest.raises(bounded.InputError, match="/proc/kmsg"):
            bounded.read_bytes("/proc/kmsg", wait=0.5)
    # a writer that comes within the wait is read to its end
    writer = threading.Thread(target=lambda: Path(fifo).write_text("a: 1\n"))
    writer.start()
    assert bounded.read_bytes(fifo, wait=TIMEOUT) == b"a: 1\n"
    writer.join()


@pytest.mark.parametrize("command", [("rosparam", "load"), ("ros2", "param", "load", "/x")])
def test_sigterm_ends_a_load_waiting_on_a_named_pipe(tmp_path, command):
    fifo = _fifo(tmp_path)
    process = subprocess.Popen(
        [str(BIN / command[0]), *command[1:], fifo], stderr=subprocess.PIPE, text=True
    )
    deadline = time.monotonic() + TIMEOUT
    while fifo not in _open_files(process.pid):  # once open, the command waits on it
        assert process.poll() is None, process.stderr.read()
        assert time.monotonic() < deadline, "the command never opened the pipe"
        time.sleep(0.05)
    started = time.monotonic()
    process.terminate()
    try:
        _, err = process.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        process.kill()
        pytest.fail("SIGTERM did not end the command")
    # ended by SIGTERM, not by the 10 s bound on the wait
    assert time.monotonic() - started < bounded_wait(), err
    assert process.returncode != 0 and "Traceback" not in err


def _open_files(pid: int) -> set[str]:
    """What the process has open (its descriptors come and go while we look)."""
    targets = set()
    try:
        fds = os.listdir(f"/proc/{pid}/fd")
    except OSError:
        return targets
    for fd in fds:
        with contextlib.suppress(OSError):
            targets.add(os.readlink(f"/proc/{pid}/fd/{fd}"))
    return targets


def bounded_wait() -> float:
    from ros_tutorials_common import bounded

    return bounded.MAX_INPUT_WAIT


@pytest.mark.parametrize("tool_name", [("rosbag", "record"), ("ros2", "bag", "record")])
def test_bag_record_refuses_a_topic_name_that_can_never_appear(tmp_path, tool_name):
    """It waited for ever for '/bad topic'."""
    line = fails(*tool_name, "-o", str(tmp_path / "bag"), "bad topic")
    assert line.startswith("error: invalid topic name '/bad topic'")
    assert not (tmp_path / "bag").exists()


def test_bag_record_refuses_an_output_name_too_long_for_the_file_system(tmp_path):
    line = fails("rosbag", "record", "-O", str(tmp_path / ("a" * 5000)), "/chatter")
    assert "File name too long" in line and "characters)" in line and len(line) < 300
