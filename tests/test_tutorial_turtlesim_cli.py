"""The official Jazzy tutorials "Using turtlesim, ros2, and rqt", "Using rqt_console to view
logs" and "Launching nodes", typed as the pages print them: `ros2 run`, `ros2 launch`.

The pages' commands are typed verbatim; what the pages show is checked where this project
prints it (the node's first log lines, the wall warnings in the console, the log level).
"""

from __future__ import annotations

import re

from helpers import fails, ok, run, script

HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
MOVE = "{linear: {x: 2.0, y: 0.0, z: 0.0}, angular: {x: 0.0,y: 0.0,z: 0.0}}"  # as the page types it


def test_ros2_run_turtlesim_node_prints_what_the_page_shows(node_process):
    sim = node_process(script("ros2"), "run", "turtlesim", "turtlesim_node", env=HEADLESS)
    sim.wait_for_text("Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]")
    page = [
        "[INFO] [turtlesim]: Starting turtlesim with node name /turtlesim",
        "[INFO] [turtlesim]: Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], "
        "theta=[0.000000]",
    ]
    # The lines as the page shows them, once the time stamp is taken out (and in that order;
    # headless, one more line says where the picture is).
    shown = [re.sub(r" \[\d+\.\d+\]", "", line) for line in sim.output.splitlines()]
    assert [line for line in shown if line in page] == page


def test_rqt_console_shows_the_wall_warnings_and_log_level_warn_hides_info(node_process):
    # Using-Rqt-Console: `ros2 run rqt_console rqt_console` (in the terminal here: no window),
    # then turtlesim with --log-level WARN, then a publisher that drives it into the wall.
    console = node_process(script("ros2"), "run", "rqt_console", "rqt_console", env=HEADLESS)
    sim = node_process(
        script("ros2"),
        "run",
        "turtlesim",
        "turtlesim_node",
        "--ros-args",
        "--log-level",
        "WARN",
        env=HEADLESS,
    )
    node_process(script("ros2"), "topic", "pub", "-r", "1", "/turtle1/cmd_vel",
                 "geometry_msgs/msg/Twist", MOVE)  # fmt: skip
    warning = "Oh no! I hit the wall!"
    console.wait_for_output(
        lambda lines: any(warning in line and "WARN" in line for line in lines),
        what="the wall warning in the console",
    )
    sim.wait_for_text(warning)
    assert "Starting turtlesim" not in sim.output  # INFO is below the level WARN
    assert "Spawning turtle" not in console.output


def test_ros2_launch_names_turtlesims_launch_files_in_all_formats():
    # Launching-Multiple-Nodes types `ros2 launch turtlesim multisim.launch.py` (it runs:
    # tests/test_launch_tutorials.py); a misspelt name lists what there is.
    line = fails("ros2", "launch", "turtlesim", "multisim_launch.py")
    assert line == (
        "error: turtlesim has no launch file 'multisim_launch.py'; it has: multisim.launch, "
        "multisim.launch.py, multisim.launch.xml, turtlesim_teleop.launch, "
        "turtlesim_teleop.launch.xml"
    )


def test_ros2_run_names_unknown_packages_and_executables_as_ros2run_does():
    assert fails("ros2", "run", "no_such_package", "talker").startswith(
        "error: Package 'no_such_package' not found ("
    )
    line = fails("ros2", "run", "turtlesim", "no_such_node")
    assert line.startswith("error: No executable found (") and "turtlesim_node" in line
    usage = run("ros2", "run")
    assert usage.returncode == 2 and usage.stderr.startswith("usage: ros2 run [-h] [--prefix")


def test_ros2_run_prefix_goes_before_the_executable():
    # ros2run's --prefix (`--prefix 'gdb -ex run --args'`): here `echo`, which prints the line.
    out = ok("ros2", "run", "--prefix", "echo prefixed", "turtlesim", "turtlesim_node")
    assert out.startswith("prefixed ") and "ros_tutorials_turtlesim.turtlesim_node" in out


def test_a_misspelled_ros_args_is_named():
    # (Before: "__node:=x: unknown special argument", about the words after it.)
    line = fails("ros2", "run", "turtlesim", "turtlesim_node", "--ros-arg", "-r", "__node:=x")
    assert line == "error: --ros-arg: did you mean --ros-args?"
