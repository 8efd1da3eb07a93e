"""turtle_tf2_py and tf2_tools as "Introducing tf2" runs them: `ros2 launch turtle_tf2_py
turtle_tf2_demo.launch.py` (turtle2 follows turtle1), the fixed and dynamic frame demos (it
follows carrot1), `ros2 run turtle_tf2_py ...`, and `ros2 run tf2_tools view_frames` (the log
lines, frames_<date>.gv as ROS 2's view_frames writes it, and the SVG picture)."""

from __future__ import annotations

import math
import re
import signal
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from helpers import NodeProcess, fails, ok, run, script, spin_until
from rclpy.node import Node
from turtlesim.msg import Pose

from tf2_tools.view_frames import frames_from_yaml, to_dot, to_model

HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
FOLLOW_TIMEOUT = 90.0  # turtle2 moves once a second; slow on a loaded 2-core machine
TURTLE1 = (5.544445, 5.544445)  # where turtlesim puts turtle1


class Turtles:
    """The test's node: the turtles' latest poses."""

    def __init__(self, executor) -> None:
        self.executor = executor
        self.node = Node("turtle_tf2_watcher", context=executor.context)
        executor.add_node(self.node)
        self.poses: dict[str, Pose] = {}
        for name in ("turtle1", "turtle2"):
            self.node.create_subscription(
                Pose, f"/{name}/pose", lambda pose, name=name: self.poses.update({name: pose}), 10
            )

    def until(self, turtle: str, condition, what: str) -> Pose:
        def holds() -> bool:
            pose = self.poses.get(turtle)
            return pose is not None and condition((pose.x, pose.y))

        spin_until(self.executor, holds, FOLLOW_TIMEOUT, what)
        return self.poses[turtle]


def ros2(node_process, *args: str) -> NodeProcess:
    return node_process(script("ros2"), *args, env=HEADLESS)


@pytest.fixture
def launched() -> Iterator[Callable[..., NodeProcess]]:
    """`ros2 launch ...` started cold, as tests/warm.py says the launcher must be (forked
    from the warm-start server, it may die by SIGSEGV at exit); killed at the end."""
    started: list[NodeProcess] = []

    def launch(*args: str, env: dict[str, str] | None = None) -> NodeProcess:
        started.append(
            NodeProcess(script("ros2"), "launch", *args, env={**HEADLESS, **(env or {})}, cold=True)
        )
        return started[-1]

    yield launch
    for process in started:
        process.kill()


def stop(process: NodeProcess) -> None:
    assert process.interrupt() in (0, 130)
    assert "Traceback" not in process.output, process.output[-4000:]


def test_demo_turtle2_follows_turtle1_and_view_frames_draws_the_tree(
    launched, node_process, executor, tmp_path
):
    turtles = Turtles(executor)
    launch = launched("turtle_tf2_py", "turtle_tf2_demo.launch.py")
    try:
        launch.wait_for_text("Successfully spawned turtle2", timeout=FOLLOW_TIMEOUT)
        turtles.until(
            "turtle2", lambda at: math.dist(at, TURTLE1) < 1.0, "turtle2 to reach turtle1"
        )
        # view_frames listens 5 s by design, then starts its layout: FOLLOW_TIMEOUT, not run's
        # 30 s, which a 6-worker suite on a loaded 2-core machine can use up.
        shown = run(
            "ros2", "run", "tf2_tools", "view_frames", cwd=str(tmp_path), timeout=FOLLOW_TIMEOUT
        )
        # The page's tf2_echo: turtle1 seen from turtle2, which has just reached it.
        echo = ros2(node_process, "run", "tf2_ros", "tf2_echo", "turtle2", "turtle1")
        try:
            echo.wait_for_text("- Matrix:", count=2)  # the first transform printed whole
            near = re.search(r"- Translation: \[(\S+), (\S+), 0\.000\]", echo.output)
            assert near and math.hypot(float(near[1]), float(near[2])) < 1.0, echo.output
        finally:
            stop(echo)
    finally:
        stop(launch)
    assert shown.returncode == 0, shown.stderr
    lines = [
        re.sub(r"^\[INFO\] \[[\d.]+\] \[view_frames\]: ", "", x) for x in shown.stderr.splitlines()
    ]
    assert lines[:2] == ["Listening to tf data for 5.0 seconds...", "Generating graph..."]
    assert lines[2].startswith("Result:tf2_msgs.srv.FrameGraph_Response(frame_yaml=")
    [gv] = tmp_path.glob("frames_*.gv")
    assert re.fullmatch(r"frames_\d{4}-\d\d-\d\d_\d\d\.\d\d\.\d\d\.gv", gv.name)
    assert lines[3:] == [f"Exporting graph in {gv.stem}.svg file..."]
    text = gv.read_text()
    for turtle in ("turtle1", "turtle2"):
        assert f'"world" -> "{turtle}"[label=" Broadcaster: ' in text, text
    assert text.endswith('}->"world";\n}')
    svg = (tmp_path / f"{gv.stem}.svg").read_text()
    assert svg.startswith("<svg") and all(f">{n}<" in svg for n in ("world", "turtle1", "turtle2"))


@pytest.mark.parametrize("kind", ["fixed", "dynamic"])
def test_frame_demos_turtle2_follows_the_carrot(launched, executor, kind):
    """The fixed carrot is 2 m to turtle1's left (turtle1 faces +x): turtle2 drives there.
    The dynamic one jumps 10 m either side of turtle1 each second: turtle2 sets off."""
    turtles = Turtles(executor)
    launch = launched("turtle_tf2_py", f"turtle_tf2_{kind}_frame_demo.launch.py")
    try:
        if kind == "fixed":
            carrot = (TURTLE1[0], TURTLE1[1] + 2.0)
            turtles.until("turtle2", lambda at: math.dist(at, carrot) < 1.0, "turtle2 at carrot1")
        else:
            launch.wait_for_text("Successfully spawned turtle2", timeout=FOLLOW_TIMEOUT)
            turtles.until(
                "turtle2", lambda at: math.dist(at, (4.0, 2.0)) > 1.0, "turtle2 to set off"
            )
    finally:
        stop(launch)


def test_static_broadcaster_latches_its_transform(node_process):
    node = ros2(
        node_process,
        "run",
        "turtle_tf2_py",
        "static_turtle_tf2_broadcaster",
        "mystaticturtle",
        "0",
        "0",
        "1",
        "0",
        "0",
        "0",
    )
    try:
        echoed = ok(
            "ros2",
            "topic",
            "echo",
            "--qos-reliability",
            "reliable",
            "--qos-durability",
            "transient_local",
            "/tf_static",
            "--once",
        )
        # The page's own line: echo takes the publisher's durability (transient local).
        plain = ok("ros2", "topic", "echo", "/tf_static", "--once")
    finally:
        stop(node)
    assert plain == echoed
    assert "    frame_id: world\n  child_frame_id: mystaticturtle\n" in echoed, echoed
    assert "    translation:\n      x: 0.0\n      y: 0.0\n      z: 1.0\n" in echoed, echoed


def test_static_broadcaster_refuses_a_wrong_count_and_world():
    result = run("ros2", "run", "turtle_tf2_py", "static_turtle_tf2_broadcaster", "a")
    assert result.returncode == 1 and "Invalid number of parameters" in result.stderr
    result = run(
        "ros2", "run", "turtle_tf2_py", "static_turtle_tf2_broadcaster",
        "world", "0", "0", "0", "0", "0", "0",
    )  # fmt: skip
    assert result.returncode == 2 and 'Your static turtle name cannot be "world"' in result.stderr
    result = run(
        "ros2", "run", "turtle_tf2_py", "static_turtle_tf2_broadcaster",
        "turtle", "0", "0", "one", "0", "0", "0",
    )  # fmt: skip
    assert result.returncode == 1, result.stderr
    assert result.stderr.strip().endswith(
        "x y z roll pitch yaw must be numbers: could not convert string to float: 'one'"
    ), result.stderr
    assert "Traceback" not in result.stderr


def test_view_frames_with_no_tf_data_and_bad_options(tmp_path, own_domain):
    name = tmp_path / "empty"
    ok("ros2", "run", "tf2_tools", "view_frames", "-t", "0.5", "-o", str(name))
    assert Path(f"{name}.gv").read_text() == 'digraph G { "No tf data received" }'
    assert ">No tf data received<" in Path(f"{name}.svg").read_text()
    said = fails("ros2", "run", "tf2_tools", "view_frames", "-t", "-1")
    assert said.startswith("view_frames: error: argument --wait-time/-t: ")
    # It listens first, as ROS 2's does; then one line says why nothing was written.
    result = run("ros2", "run", "tf2_tools", "view_frames", "-t", "0.1", "-o", "/nonexistent/x")
    assert result.returncode == 1 and "Traceback" not in result.stderr
    assert result.stderr.splitlines()[-1] == (
        "view_frames: cannot write '/nonexistent/x.gv': No such file or directory"
    )


YAML = """turtle1: \n  parent: 'world'\n  broadcaster: 'default_authority'\n  rate: 62.543
  most_recent_transform: 1700000010.000\n  oldest_transform: 1700000005.000
  buffer_length: 5.000\ncarrot1: \n  parent: 'turtle1'\n  broadcaster: 'default_authority'
  rate: 10.000\n  most_recent_transform: 1700000010.000\n  oldest_transform: 1700000005.000
  buffer_length: 5.000\n"""


def test_the_dot_file_is_view_frames_own_and_the_picture_has_each_frame():
    frames = frames_from_yaml(YAML)
    assert to_dot(frames, 1700000010.5) == (
        "digraph G {\n"
        '"world" -> "turtle1"[label=" Broadcaster: default_authority\\nAverage rate: 62.543\\n'
        "Buffer length: 5.0\\nMost recent transform: 1700000010.0\\nOldest transform: "
        '1700000005.0\\n"];\n'
        '"turtle1" -> "carrot1"[label=" Broadcaster: default_authority\\nAverage rate: 10.0\\n'
        "Buffer length: 5.0\\nMost recent transform: 1700000010.0\\nOldest transform: "
        '1700000005.0\\n"];\n'
        "edge [style=invis];\n"
        ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n'
        '"Recorded at time: 1700000010.5"[ shape=plaintext ] ;\n'
        '}->"world";\n}'
    )
    model = to_model(frames, 1700000010.5)
    assert {v.label for v in model.vertices.values() if v.kind == "topic"} == {
        "world",
        "turtle1",
        "carrot1",
    }
    assert frames_from_yaml("[]") == {} and to_dot({}, 0.0).startswith('digraph G { "No tf')


@pytest.mark.parametrize("stop_signal", [signal.SIGINT, signal.SIGTERM])
def test_view_frames_ends_at_once_on_ctrl_c_and_sigterm(node_process, tmp_path, stop_signal):
    """While it listens: Ctrl-C or SIGTERM ends it with status 130, no traceback, no files."""
    name = tmp_path / "frames"
    tool = ros2(node_process, "run", "tf2_tools", "view_frames", "-t", "600", "-o", str(name))
    tool.wait_for_text("Listening to tf data for 600.0 seconds...")
    tool.process.send_signal(stop_signal)
    assert tool.wait() == 130, tool.output
    assert "Traceback" not in tool.output, tool.output
    assert not list(tmp_path.iterdir())


# The launch tutorials' package launch_tutorial, the Large Projects page's files among them.
TUTORIAL_PREFIX = Path(__file__).parent / "data" / "launch_tutorial"


def test_launch_for_large_projects_page_runs_turtle_tf2_py(launched, executor):
    """The page "Using ROS 2 launch for large projects" (Intermediate > Launch): its launch
    files as printed (tests/data/launch_tutorial/); `ros2 launch launch_tutorial
    launch_turtlesim_launch.py` runs two turtlesims, turtle_tf2_py's broadcasters and listener
    (turtle2 drives to carrot1), mimic (turtlesim2's turtle1 copies turtle2) and the fixed
    frame broadcaster named after $USER; rviz2 with turtle_rviz.rviz prints the link to its
    3D view (no display here: no window)."""
    turtles = Turtles(executor)
    copied: list[Pose] = []
    turtles.node.create_subscription(Pose, "/turtlesim2/turtle1/pose", copied.append, 10)
    env = {"AMENT_PREFIX_PATH": str(TUTORIAL_PREFIX), "USER": "learner"}
    launch = launched("launch_tutorial", "launch_turtlesim_launch.py", env=env)
    try:
        launch.wait_for_text("[rviz2]: Open http://127.0.0.1:")
        carrot = (TURTLE1[0], TURTLE1[1] + 2.0)
        turtles.until("turtle2", lambda at: math.dist(at, carrot) < 1.0, "turtle2 at carrot1")
        spin_until(
            executor,
            lambda: copied and math.dist((copied[-1].x, copied[-1].y), TURTLE1) > 0.5,
            FOLLOW_TIMEOUT,
            "turtlesim2's turtle1 to mimic turtle2",
        )
        nodes = ok("ros2", "node", "list").splitlines()
        assert {"/turtlesim2/sim", "/sim", "/mimic", "/learner_fixed_broadcaster"} <= set(nodes)
    finally:
        stop(launch)


def test_the_rviz_file_and_the_sensor_message_demo_are_installed():
    """Introducing tf2's `ros2 run rviz2 rviz2 -d $(ros2 pkg prefix --share
    turtle_tf2_py)/rviz/turtle_rviz.rviz` names a file that is there: the world frame fixed, a
    TF display; and the stamped datatypes page's executable and launch file are in the package."""
    import yaml

    share = ok("ros2", "pkg", "prefix", "--share", "turtle_tf2_py").strip()
    config = yaml.safe_load(Path(share, "rviz", "turtle_rviz.rviz").read_text())
    manager = config["Visualization Manager"]
    assert manager["Global Options"]["Fixed Frame"] == "world"
    assert "rviz_default_plugins/TF" in [d["Class"] for d in manager["Displays"]]
    executables = ok("ros2", "pkg", "executables", "turtle_tf2_py").splitlines()
    assert "turtle_tf2_py turtle_tf2_message_broadcaster" in executables
    assert Path(share, "launch", "turtle_tf2_sensor_message.launch.py").is_file()
