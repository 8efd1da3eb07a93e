"""The launch tutorials' files run as real processes with `ros2 launch`, which prints what the
pages show: Launching-Multiple-Nodes (turtlesim's multisim.launch.py), Creating-Launch-Files
(the mimic example, YAML), Using-Substitutions (YAML, a timer) and Using-Event-Handlers
(Python: process start, output, exit and shutdown handlers, a timer)."""

from __future__ import annotations

import os
import re
import signal
from pathlib import Path

from geometry_msgs.msg import Twist
from helpers import ok
from test_turtlesim_processes import HEADLESS, Watcher

TUTORIAL_PREFIX = Path(__file__).parent / "data" / "launch_tutorial"
# The tutorials' package in a sourced workspace; USER for the Using-Event-Handlers message.
WORKSPACE = {**HEADLESS, "AMENT_PREFIX_PATH": str(TUTORIAL_PREFIX), "USER": "learner"}


def _launch(node_process, *args: str):
    return node_process("-m", "ros2cmd", "launch", *args, env=WORKSPACE)  # `ros2 launch ...`


def _pid(output: str, name: str) -> int:
    return int(re.search(rf"\[INFO\] \[{name}\]: process started with pid \[(\d+)\]", output)[1])


def _spawned_both(lines: list[str]) -> bool:
    return sum("Spawning turtle [turtle1]" in line for line in lines) == 2


def test_multisim_launch_py_starts_two_simulators(node_process):
    # Launching-Multiple-Nodes: `ros2 launch turtlesim multisim.launch.py`
    launch = _launch(node_process, "turtlesim", "multisim.launch.py")
    launch.wait_for_output(_spawned_both, what="both simulators' turtle1")
    lines = launch.output.splitlines()
    # As ros2 launch prints it: where the logs are, then each process by its executable's name
    log_dir = Path(os.environ.get("ROS_LOG_DIR") or Path.home() / ".ros" / "log")
    assert re.fullmatch(
        rf"\[INFO\] \[launch\]: All log files can be found below {re.escape(str(log_dir))}/"
        r"\d{4}(-\d\d){5}-\d{6}-.+-\d+",
        lines[0],
    ), lines[0]
    assert lines[1] == "[INFO] [launch]: Default logging verbosity is set to INFO"
    started = [line for line in lines if "process started" in line]
    assert [re.sub(r"\d+\]$", "N]", line) for line in started] == [
        "[INFO] [turtlesim_node-1]: process started with pid [N]",
        "[INFO] [turtlesim_node-2]: process started with pid [N]",
    ]
    node_line = r"\[turtlesim_node-1\] \[INFO\] \[\d+\.\d+\] \[turtlesim1\.turtlesim\]: Spawning "
    assert any(re.match(node_line, line) for line in lines)  # each line prefixed by its process
    assert "[turtlesim2.turtlesim]: Spawning turtle [turtle1]" in launch.output
    assert "mimic" not in launch.output
    pids = [_pid(launch.output, f"turtlesim_node-{n}") for n in (1, 2)]
    assert launch.interrupt() == 130
    for n, pid in enumerate(pids, 1):
        assert f"[INFO] [turtlesim_node-{n}]: process has finished cleanly [pid {pid}]" in (
            launch.output
        )
    assert "[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)" in launch.output
    # ros2 launch says nothing else of its own while it stops them
    assert [line for line in launch.output.splitlines() if line.startswith("[INFO] [launch]")] == (
        lines[:2]
    )
    assert "Traceback" not in launch.output, launch.output[-4000:]


def test_creating_launch_files_mimic_example_in_yaml(node_process, executor):
    launch = _launch(node_process, "launch_tutorial", "turtlesim_mimic_launch.yaml")
    launch.wait_for_output(_spawned_both, what="both simulators' turtle1")
    watcher = Watcher(executor, "/turtlesim2/turtle1/pose")
    twist = Twist()
    twist.linear.x, twist.angular.z = 2.0, -1.8  # the page's `ros2 topic pub` command
    watcher.publish_until(
        "/turtlesim1/turtle1/cmd_vel",
        twist,
        lambda p: p.linear_velocity == 2.0 and abs(p.angular_velocity + 1.8) < 1e-6,
        "turtlesim2's turtle to follow turtlesim1's",
    )
    assert launch.interrupt() == 130


def test_using_substitutions_yaml_changes_the_background_after_two_seconds(node_process):
    # `ros2 launch launch_tutorial example_main_launch.yaml`, as the page types it: its
    # $(eval "200 == 200 and True") needs no --allow-code (no code runs to compute it)
    launch = _launch(node_process, "launch_tutorial", "example_main_launch.yaml")
    launch.wait_for_text("[INFO] [ros2-4]: process started")  # the timer's `ros2 param set`
    launch.wait_for_text(
        f"[INFO] [ros2-4]: process has finished cleanly [pid {_pid(launch.output, 'ros2-4')}]"
    )
    assert "Spawning turtle [turtle2] at x=[5.000000], y=[2.000000]" in launch.output
    value = ok("ros2", "param", "get", "/turtlesim2/sim", "background_r")
    assert value == "Integer value is: 200\n"
    # Each process's output (the `ros2` commands' is not on the screen) is in the log folder
    # under the name the screen gives it: ros2-2 is the spawn, ros2-3 and ros2-4 set the colour.
    log_dir = Path(re.search(r"All log files can be found below (\S+)", launch.output)[1])
    assert "turtlesim.srv.Spawn_Response(name='turtle2')" in (log_dir / "ros2-2.log").read_text()
    for name in ("ros2-3", "ros2-4"):
        assert (log_dir / f"{name}.log").read_text() == "Set parameter successful\n"
    assert launch.interrupt() == 130


def test_using_event_handlers_as_the_page_describes(node_process):
    launch = _launch(
        node_process,
        "launch_tutorial",
        "example_event_handlers_launch.py",
        "use_provided_red:=True",
        "new_background_r:=200",
    )
    # Start turtlesim, then (OnProcessStart) spawn the second turtle; its output (OnProcessIO);
    # when the spawn is done (OnExecutionComplete) purple, and pink two seconds later.
    launch.wait_for_text("[INFO] [ros2-4]: process has finished cleanly")
    lines = launch.output.splitlines()
    said = [line for line in lines if line.startswith("[INFO] [launch.user]: ")]  # LogInfo
    assert said[0] == "[INFO] [launch.user]: Turtlesim started, spawning turtle"
    assert '[INFO] [launch.user]: Spawn request says "response:"' in said
    assert said[-1] == "[INFO] [launch.user]: Spawn finished"
    spawned = f"[INFO] [ros2-2]: process has finished cleanly [pid {_pid(launch.output, 'ros2-2')}]"
    assert lines.index(spawned) < lines.index("[INFO] [launch.user]: Spawn finished")
    assert lines.index("[INFO] [launch.user]: Spawn finished") < lines.index(
        f"[INFO] [ros2-3]: process started with pid [{_pid(launch.output, 'ros2-3')}]"
    )
    value = ok("ros2", "param", "get", "/turtlesim1/sim", "background_r")
    assert value == "Integer value is: 200\n"
    # Closing the window ends turtlesim: OnProcessExit logs and emits Shutdown; OnShutdown.
    os.kill(_pid(launch.output, "turtlesim_node-1"), signal.SIGINT)
    assert launch.wait() == 0
    assert "[INFO] [launch.user]: learner closed the turtlesim window" in launch.output
    assert "[INFO] [launch.user]: Launch was asked to shutdown: Window closed" in launch.output
    assert "[INFO] [launch]: " not in launch.output.split("Spawn finished")[1]  # no line of its own
    assert "Traceback" not in launch.output, launch.output[-4000:]


def test_using_event_handlers_without_user_fails_as_ros2_launch(node_process, monkeypatch):
    # In a container USER is often unset: the page's EnvironmentVariable(name='USER') has no
    # default, so ros2 launch's handler fails when the window closes; it says so at ERROR,
    # shuts down with that reason (OnShutdown logs it) and exits 1.
    monkeypatch.delenv("USER", raising=False)
    env = {key: value for key, value in WORKSPACE.items() if key != "USER"}
    launch = node_process(
        "-m", "ros2cmd", "launch", "launch_tutorial", "example_event_handlers_launch.py", env=env
    )
    launch.wait_for_text("[INFO] [launch.user]: Spawn finished")
    os.kill(_pid(launch.output, "turtlesim_node-1"), signal.SIGINT)
    assert launch.wait() == 1
    # ros2 launch's line; here the launch file's line is named before the reason
    failure = (
        re.escape("Caught exception in launch (see debug for traceback): ")
        + (r"\S+/example_event_handlers_launch\.py:\d+: ")
        + re.escape("environment variable 'USER' does not exist")
    )
    lines = launch.output.splitlines()
    assert [line for line in lines if re.fullmatch(rf"\[ERROR\] \[launch\]: {failure}", line)]
    asked = rf"\[INFO\] \[launch\.user\]: Launch was asked to shutdown: {failure}"
    assert [line for line in lines if re.fullmatch(asked, line)], launch.output[-3000:]
    assert "Window closed" not in launch.output  # the handler's later actions do not run
    assert "Traceback" not in launch.output, launch.output[-4000:]
