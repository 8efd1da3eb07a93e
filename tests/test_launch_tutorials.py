"""The launch tutorials' files run as real processes with the launcher (`ros2 launch`):
Launching-Multiple-Nodes (turtlesim's multisim.launch.py), Creating-Launch-Files (the mimic
example, YAML), Using-Substitutions (YAML, a timer) and Using-Event-Handlers (Python: process
start, output, exit and shutdown handlers, a timer)."""

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
    return node_process("-m", "launcher", *args, env=WORKSPACE)


def _spawned_both(lines: list[str]) -> bool:
    return sum("Spawning turtle [turtle1]" in line for line in lines) == 2


def test_multisim_launch_py_starts_two_simulators(node_process):
    # Launching-Multiple-Nodes: `ros2 launch turtlesim multisim.launch.py`
    launch = _launch(node_process, "turtlesim", "multisim.launch.py")
    launch.wait_for_output(_spawned_both, what="both simulators' turtle1")
    out = launch.output
    assert "[turtlesim1.turtlesim]: Spawning turtle [turtle1]" in out
    assert "[turtlesim2.turtlesim]: Spawning turtle [turtle1]" in out
    assert "mimic" not in out
    assert launch.interrupt() == 130
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
    # `ros2 launch launch_tutorial example_main_launch.yaml` ($(eval) asks for --allow-code)
    launch = _launch(node_process, "launch_tutorial", "example_main_launch.yaml", "--allow-code")
    launch.wait_for_text("[launcher] started ros2-3")  # the timer's `ros2 param set ... 200`
    launch.wait_for_text("[launcher] ros2-3 exited cleanly")
    assert "Spawning turtle [turtle2] at x=[5.000000], y=[2.000000]" in launch.output
    value = ok("ros2", "param", "get", "/turtlesim2/sim", "background_r")
    assert value == "Integer value is: 200\n"
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
    launch.wait_for_text("[launcher] ros2-3 exited cleanly")
    lines = [line for line in launch.output.splitlines() if line.startswith("[launcher] ")]
    said = [line for line in lines if not re.match(r"\[launcher\] (started|logging|ros2)", line)]
    assert said[0] == "[launcher] Turtlesim started, spawning turtle"
    assert '[launcher] Spawn request says "response:"' in said
    assert said[-1] == "[launcher] Spawn finished"
    assert lines.index("[launcher] Spawn finished") < lines.index(
        "[launcher] ros2-2 exited cleanly"
    )
    value = ok("ros2", "param", "get", "/turtlesim1/sim", "background_r")
    assert value == "Integer value is: 200\n"
    # Closing the window ends turtlesim: OnProcessExit logs and emits Shutdown; OnShutdown.
    pid = int(re.search(r"started turtlesim1/sim \(pid (\d+)\)", launch.output).group(1))
    os.kill(pid, signal.SIGINT)
    assert launch.wait() == 0
    assert "[launcher] learner closed the turtlesim window" in launch.output
    assert "[launcher] Launch was asked to shutdown: Window closed" in launch.output
    assert "Traceback" not in launch.output, launch.output[-4000:]
