"""The official Jazzy tf2 pages typed as a learner: "Writing a static broadcaster (Python)",
"Writing a broadcaster (Python)", "Writing a listener (Python)", "Adding a frame (Python)",
"Using stamped datatypes with tf2_ros::MessageFilter" (its Python part),
"Quaternion fundamentals" and "Debugging".

One workspace for the whole module, as the pages build one package, learning_tf2_py, page
after page: `ros2 pkg create`, the pages' files (tests/data/workspace/tf2/, as printed), the
package.xml and setup.py lines they add, the real colcon build. Then each page's commands in
new terminals that source install/setup.bash, and what they print or do: the static transform
on /tf_static, tf2_echo's pose of turtle1, turtle2 following turtle1 (and the carrot).
"""

from __future__ import annotations

import fcntl
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import NodeProcess, error_reports, spin_until
from rclpy.node import Node
from test_workspace import (
    BUILD_TIMEOUT,
    DATA,
    activated,
    add_entry_points,
    add_line_after,
    bash,
    ok,
    sourced,
    terminal,
)
from turtlesim.msg import Pose

from ros_tutorials_common.shutdown import CONVERSION_FAILED, SHUT_DOWN_CONTEXT

TF2 = DATA / "tf2"
PAGE_FILES = [
    "static_turtle_tf2_broadcaster.py",
    "turtle_tf2_broadcaster.py",
    "turtle_tf2_listener.py",
    "fixed_frame_tf2_broadcaster.py",
    "dynamic_frame_tf2_broadcaster.py",
    "turtle_tf2_message_broadcaster.py",  # the stamped datatypes page's download
]
LAUNCH_FILES = [
    "turtle_tf2_demo_launch.py",  # as the listener page leaves it
    "turtle_tf2_fixed_frame_demo_launch.py",
    "turtle_tf2_dynamic_frame_demo_launch.py",
    "turtle_tf2_sensor_message_launch.py",
]
# The pages' package.xml lines (static broadcaster page, then the broadcaster page's launch ones).
EXEC_DEPENDS = [
    "geometry_msgs",
    "python3-numpy",
    "rclpy",
    "tf2_ros_py",
    "turtlesim",
    "launch",
    "launch_ros",
]
FOLLOW_TIMEOUT = 90.0  # turtle2 moves once a second; slow on a loaded 2-core machine
TURTLE1 = (5.544445, 5.544445)  # where turtlesim puts turtle1


def learning_tf2_py(workspace: Path) -> None:
    """learning_tf2_py as the pages leave it, built with colcon; with the Debugging page's
    listener (turtle_tf2_listener_debug: its two bugs, made in the Python listener) and launch
    file (learning_tf2_cpp there), so that one build serves every page."""
    (workspace / "src").mkdir(parents=True)
    ok(
        activated(
            "ros2 pkg create --build-type ament_python --license Apache-2.0 -- learning_tf2_py"
        ),
        workspace / "src",
    )
    package = workspace / "src" / "learning_tf2_py"
    for name in PAGE_FILES:
        (package / "learning_tf2_py" / name).write_text((TF2 / name).read_text())
    (package / "launch").mkdir()
    for name in LAUNCH_FILES:
        (package / "launch" / name).write_text((TF2 / name).read_text())
    for depend in reversed(EXEC_DEPENDS):
        add_line_after(
            package / "package.xml", "<license>", f"  <exec_depend>{depend}</exec_depend>"
        )
    setup_py = package / "setup.py"
    add_entry_points(
        setup_py,
        *(f"{name[:-3]} = learning_tf2_py.{name[:-3]}:main" for name in PAGE_FILES),
        "turtle_tf2_listener_debug = learning_tf2_py.turtle_tf2_listener_debug:main",
    )
    # The broadcaster page's 2.3: the launch files in data_files, and the imports.
    add_line_after(
        setup_py,
        "('share/' + package_name, ['package.xml']),",
        "        (os.path.join('share', package_name, 'launch'), "
        "glob(os.path.join('launch', '*launch.[pxy][yma]*'))),",
    )
    setup_py.write_text("import os\nfrom glob import glob\n" + setup_py.read_text())
    # Debugging, 1: to_frame_rel 'turtle3', and the lookup at `now`.
    debug = (TF2 / "turtle_tf2_listener.py").read_text()
    debug = debug.replace("to_frame_rel = 'turtle2'", "to_frame_rel = 'turtle3'")
    debug = debug.replace("rclpy.time.Time())", "self.get_clock().now())")
    assert debug.count("'turtle3'") == 1 and "get_clock().now())" in debug
    (package / "learning_tf2_py" / "turtle_tf2_listener_debug.py").write_text(debug)
    debug_launch = (TF2 / "start_tf2_debug_demo_launch.py").read_text()
    (package / "launch" / "start_tf2_debug_demo_launch.py").write_text(
        debug_launch.replace("learning_tf2_cpp", "learning_tf2_py")
    )
    # The pages' rosdep line, before the build: every dependency is here.
    checked = ok(activated("rosdep install -i --from-path src --rosdistro jazzy -y"), workspace)
    assert "#All required rosdeps installed successfully" in checked
    built = ok(
        activated("colcon build --packages-select learning_tf2_py"), workspace, BUILD_TIMEOUT
    )
    assert "Summary: 1 package finished" in built


@pytest.fixture(scope="module")
def workspace(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The one learning_tf2_py workspace of this run: the pytest processes of one run
    (pytest-xdist) share it; the first builds it, under a lock, the others wait for it."""
    base = tmp_path_factory.getbasetemp()
    root = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base
    workspace = root / "tf2_pages" / "ros2_ws"
    workspace.parent.mkdir(exist_ok=True)
    with open(workspace.parent / "build.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # released when the file closes
        if not (workspace.parent / "built").exists():
            shutil.rmtree(workspace, ignore_errors=True)
            learning_tf2_py(workspace)
            (workspace.parent / "built").touch()
    return workspace


class Turtles:
    """The test's node: the turtles' poses as turtlesim publishes them."""

    def __init__(self, executor) -> None:
        self.executor = executor
        self.node = Node("tf2_page_watcher", context=executor.context)
        executor.add_node(self.node)
        self.poses: dict[str, Pose] = {}
        for name in ("turtle1", "turtle2"):
            self.node.create_subscription(
                Pose, f"/{name}/pose", lambda pose, name=name: self.poses.update({name: pose}), 10
            )

    def until_near(self, turtle: str, where: tuple[float, float], what: str) -> Pose:
        def near() -> bool:
            pose = self.poses.get(turtle)
            return pose is not None and math.dist((pose.x, pose.y), where) < 1.0

        spin_until(self.executor, near, FOLLOW_TIMEOUT, what)
        return self.poses[turtle]

    def until_moved(self, turtle: str, start: tuple[float, float], what: str) -> None:
        def moved() -> bool:
            pose = self.poses.get(turtle)
            return pose is not None and math.dist((pose.x, pose.y), start) > 1.0

        spin_until(self.executor, moved, FOLLOW_TIMEOUT, what)


def launched(workspace: Path, launch: str) -> NodeProcess:
    return terminal(workspace, f"ros2 launch learning_tf2_py {launch}")


# The pages' nodes catch only KeyboardInterrupt, then call rclpy.shutdown(), when rclpy's own
# Ctrl-C handler has already shut ROS down: in ROS 2 Jazzy that prints rclpy's traceback, as
# does a spin or timer that meets the shut-down context first ("context is not valid"); a
# Ctrl-C that lands while rclpy's C++ converts a message comes out as pybind11's RuntimeError
# (ros_tutorials_common/shutdown.py).
ALREADY_SHUT_DOWN = "failed to shutdown: rcl_shutdown already called on the given context"


def rclpy_at_ctrl_c(error_line: str) -> bool:
    """Whether an error line is one of rclpy's at Ctrl-C above."""
    kind, _, message = error_line.partition(": ")
    return (kind == "rclpy._rclpy_pybind11.RCLError" and message.startswith(ALREADY_SHUT_DOWN)) or (
        kind in ("rclpy._rclpy_pybind11.RCLError", "RuntimeError")
        and any(words in message for words in (*SHUT_DOWN_CONTEXT, CONVERSION_FAILED))
    )


def stop(process: NodeProcess) -> None:
    """Ctrl-C, as in the terminal: the launch ends and its nodes with it; the only errors
    printed are rclpy's at Ctrl-C in the pages' nodes."""
    process.interrupt()
    for report in error_reports(process.output):
        assert rclpy_at_ctrl_c(report[-1][-1]), process.output[-4000:]


def test_static_broadcaster_publishes_on_tf_static(workspace):
    """Static broadcaster page, 4 Run: the node, then `ros2 topic echo` of /tf_static shows
    the one transform world -> mystaticturtle, 1 m up."""
    node = terminal(
        workspace,
        "ros2 run learning_tf2_py static_turtle_tf2_broadcaster mystaticturtle 0 0 1 0 0 0",
    )
    try:
        echoed = ok(
            sourced(
                "ros2 topic echo --qos-reliability reliable --qos-durability transient_local "
                "/tf_static --once"
            ),
            workspace,
        )
    finally:
        stop(node)
    assert re.fullmatch(
        r"transforms:\n- header:\n    stamp:\n      sec: \d+\n      nanosec: \d+\n"
        r"    frame_id: world\n  child_frame_id: mystaticturtle\n  transform:\n"
        r"    translation:\n      x: 0.0\n      y: 0.0\n      z: 1.0\n"
        r"    rotation:\n      x: 0.0\n      y: 0.0\n      z: 0.0\n      w: 1.0\n---\n",
        echoed,
    ), echoed


def test_static_broadcaster_refuses_world_and_a_wrong_count(workspace):
    """The page's own checks: 'world' is refused (status 2), the usage for a wrong count (1)."""
    result = bash(
        sourced("ros2 run learning_tf2_py static_turtle_tf2_broadcaster world 0 0 1 0 0 0"),
        workspace,
    )
    assert result.returncode == 2, result.stderr
    assert 'Your static turtle name cannot be "world"' in result.stderr
    result = bash(sourced("ros2 run learning_tf2_py static_turtle_tf2_broadcaster x 0"), workspace)
    assert result.returncode == 1 and "Invalid number of parameters" in result.stderr


def test_broadcaster_and_listener_turtle2_follows_turtle1(workspace, executor):
    """Broadcaster page: `ros2 launch learning_tf2_py turtle_tf2_demo_launch.py`, then
    `ros2 run tf2_ros tf2_echo world turtle1` shows turtle1's pose. Listener page: the same
    launch file spawns turtle2, which drives to turtle1."""
    turtles = Turtles(executor)
    launch = launched(workspace, "turtle_tf2_demo_launch.py")
    echo = terminal(workspace, "ros2 run tf2_ros tf2_echo world turtle1")
    try:
        echo.wait_for_text("- Translation: [5.544, 5.544, 0.000]", timeout=FOLLOW_TIMEOUT)
        echo.wait_for_text("- Rotation: in Quaternion [0.000, 0.000, 0.000, 1.000]")
        launch.wait_for_text("Successfully spawned turtle2", timeout=FOLLOW_TIMEOUT)
        turtles.until_near("turtle2", TURTLE1, "turtle2 to reach turtle1")
    finally:
        stop(echo)
        stop(launch)


def test_fixed_frame_turtle2_follows_the_carrot(workspace, executor):
    """Adding a frame, 1.5: the fixed frame demo with `target_frame:=carrot1`: turtle2 drives
    to carrot1, 2 m to turtle1's left (turtle1 faces +x: 2 m up)."""
    turtles = Turtles(executor)
    launch = launched(workspace, "turtle_tf2_fixed_frame_demo_launch.py target_frame:=carrot1")
    try:
        carrot = (TURTLE1[0], TURTLE1[1] + 2.0)
        turtles.until_near("turtle2", carrot, "turtle2 to reach carrot1")
    finally:
        stop(launch)


def test_dynamic_frame_carrot_moves_and_turtle2_follows_it(workspace, executor):
    """Adding a frame, 2: the dynamic frame demo: carrot1 jumps between 10 m left and right
    of turtle1 every second (tf2_echo shows it), and turtle2 sets off after it."""
    turtles = Turtles(executor)
    launch = launched(workspace, "turtle_tf2_dynamic_frame_demo_launch.py")
    echo = terminal(workspace, "ros2 run tf2_ros tf2_echo turtle1 carrot1")
    try:
        echo.wait_for_output(
            lambda lines: any(
                re.search(r"- Translation: \[-?0\.000, -?10\.000, 0\.000\]", x) for x in lines
            ),
            timeout=FOLLOW_TIMEOUT,
        )
        launch.wait_for_text("Successfully spawned turtle2", timeout=FOLLOW_TIMEOUT)
        turtles.until_moved("turtle2", (4.0, 2.0), "turtle2 to set off after the carrot")
    finally:
        stop(echo)
        stop(launch)


def test_stamped_datatypes_page_publishes_turtle3s_point(workspace):
    """Using stamped datatypes with tf2_ros::MessageFilter, 3 Run: the page's launch file
    starts turtlesim, the two broadcasters and turtle_tf2_py's turtle_tf2_message_broadcaster,
    which spawns turtle3, drives it in a circle and publishes where it is; `ros2 topic echo`
    shows that PointStamped in the world frame."""
    launch = launched(workspace, "turtle_tf2_sensor_message_launch.py")
    try:
        launch.wait_for_text("Successfully spawned turtle3", timeout=FOLLOW_TIMEOUT)
        echoed = ok(sourced("ros2 topic echo /turtle3/turtle_point_stamped --once"), workspace)
    finally:
        stop(launch)
    assert re.search(
        r"^  frame_id: world\npoint:\n  x: \d+\.\d+\n  y: \d+\.\d+\n  z: 0\.0\n---$",
        echoed,
        re.MULTILINE,
    ), echoed


def test_debugging_page_commands(workspace, tmp_path):
    """Debugging: the listener asking for turtle3 at `now` (the page's two bugs, in the Python
    listener), the page's launch file; tf2_echo and the listener say turtle3 does not exist;
    view_frames shows the frames that do; tf2_monitor times the chain turtle2 -> turtle1."""
    launch = launched(workspace, "start_tf2_debug_demo_launch.py")
    try:
        launch.wait_for_text(
            'Could not transform turtle3 to turtle1: "turtle3" passed to lookupTransform '
            "argument target_frame does not exist",
            timeout=FOLLOW_TIMEOUT,
        )
        echo = terminal(workspace, "ros2 run tf2_ros tf2_echo turtle3 turtle1")
        try:
            echo.wait_for_text(
                'Invalid frame ID "turtle3" passed to canTransform argument target_frame - '
                "frame does not exist"
            )
        finally:
            stop(echo)
        setup = workspace / "install" / "setup.bash"
        ok(f"source {setup}\nros2 run tf2_tools view_frames", tmp_path, timeout=120.0)
        [gv] = [path.read_text() for path in tmp_path.glob("frames_*.gv")]
        assert '"world" -> "turtle1"' in gv and '"world" -> "turtle2"' in gv, gv
        assert gv.count("->") == 3  # the two frames and the legend's invisible edge
        monitor = terminal(workspace, "ros2 run tf2_ros tf2_monitor turtle2 turtle1")
        try:
            monitor.wait_for_text("RESULTS: for turtle2 to turtle1", timeout=FOLLOW_TIMEOUT)
            monitor.wait_for_text("Net delay     avg = ")
        finally:
            stop(monitor)
    finally:
        stop(launch)


def test_quaternion_fundamentals_snippets(tmp_path):
    """Quaternion fundamentals: the page's Python snippets run as printed
    (tests/data/workspace/tf2/quaternion_fundamentals.py) and print the page's numbers; the
    page's quaternion_multiply takes w first: docs/tf2.md's reordering around it, run after
    them, gives 180 degrees about x."""
    docs = (Path(__file__).parents[1] / "docs" / "tf2.md").read_text()
    [reordering] = [b for b in docs.split("```python\n") if b.startswith("def wxyz(q):")]
    script = (TF2 / "quaternion_fundamentals.py").read_text() + (
        reordering.split("```")[0] + "print('reordered:', ' '.join(f'{v:.3f}' for v in q_new))\n"
    )
    (tmp_path / "quaternions.py").write_text(script)
    out = subprocess.run(
        [sys.executable, str(tmp_path / "quaternions.py")],
        capture_output=True,
        text=True,
        timeout=60,
        check=True,
    ).stdout
    first = re.match(
        r"The quaternion representation is x: (\S+) y: (\S+) z: (\S+) w: (\S+)\.\n", out
    )
    assert first, out
    assert [round(float(v), 3) for v in first.groups()] == [0.5, -0.5, -0.5, 0.5]
    assert "reordered: 1.000 0.000 0.000 0.000\n" in out  # 180 degrees about x
    inverted = re.search(r"inverted: \[(.*)\]", out)
    assert inverted, out
    assert [round(float(v), 3) for v in inverted[1].split()] == [0.5, -0.5, -0.5, -0.5]
