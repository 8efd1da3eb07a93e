"""The official Jazzy URDF pages typed as a learner: "Building a visual robot model from
scratch", "Building a movable robot model", "Adding physical and collision properties", "Using
Xacro to clean up your code" (`ros2 launch urdf_tutorial display.launch.py model:=...` for each
model), and "Using URDF with robot_state_publisher" (its package urdf_tutorial_r2d2: `ros2 pkg
create`, the page's files, the setup.py edits, `colcon build --symlink-install`, `ros2 launch
urdf_tutorial_r2d2 demo_launch.py`). What they publish is checked: the robot on
/robot_description, a tf frame for every link, the joints moving."""

from __future__ import annotations

import math
import os
import shlex
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import NodeProcess, run, script, spin_until
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from sensor_msgs.msg import JointState
from std_msgs.msg import String
from test_tf2_tutorials import stop as page_stop
from test_workspace import BUILD_TIMEOUT, DATA, activated, add_entry_points, ok, terminal
from tf2_msgs.msg import TFMessage

from ros_tutorials_common import urdf

ROOT = Path(__file__).resolve().parents[1]
MODELS = ROOT / "urdf_tutorial" / "urdf"
R2D2 = DATA / "urdf"
HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
# A terminal where `source .venv/bin/activate` was run: xacro on PATH, as the launch file's
# Command(['xacro ', ...]) needs it (a ROS installation's setup.bash puts it there).
ACTIVATED = {**HEADLESS, "PATH": f"{Path(sys.executable).parent}:{os.environ['PATH']}"}
XACRO = str(Path(sys.executable).parent / "xacro")
# The pages' commands: (model:=..., the joint_states publisher's node shows the sliders).
PAGES = [
    "urdf/01-myfirst.urdf",  # visual page
    "urdf/02-multipleshapes.urdf",
    "urdf/03-origins.urdf",
    "urdf/04-materials.urdf",
    "urdf/05-visual.urdf",
    "urdf/06-flexible.urdf",  # movable page
    "urdf/07-physics.urdf",  # physical and collision page
    "urdf/08-macroed.urdf.xacro",  # xacro page
]
LATE = 120.0  # a launch of four processes on a loaded 2-core machine


class Frames:
    """The test's node: /robot_description and every tf frame's parent."""

    def __init__(self, executor) -> None:
        self.executor = executor
        self.node = Node("urdf_page_watcher", context=executor.context)
        executor.add_node(self.node)
        self.description: str | None = None
        self.parents: dict[str, str] = {}  # child frame -> parent frame
        self.latest: dict[str, object] = {}  # child frame -> newest transform
        self.joint_states: list[JointState] = []
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.node.create_subscription(String, "/robot_description", self._description, latched)
        static = QoSProfile(depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.node.create_subscription(TFMessage, "/tf_static", self._tf, static)
        self.node.create_subscription(TFMessage, "/tf", self._tf, 100)
        self.node.create_subscription(JointState, "/joint_states", self.joint_states.append, 10)

    def _description(self, msg: String) -> None:
        self.description = msg.data

    def _tf(self, msg: TFMessage) -> None:
        for t in msg.transforms:
            self.parents[t.child_frame_id] = t.header.frame_id
            self.latest[t.child_frame_id] = t

    def until(self, condition, what: str, timeout: float = LATE) -> None:
        spin_until(self.executor, condition, timeout, what)


def expanded(model: str) -> str:
    """The URDF a model of urdf_tutorial stands for: what xacro makes of it (the launch file
    runs every model through xacro)."""
    return subprocess.run(
        [XACRO, str(ROOT / "urdf_tutorial" / model)],
        capture_output=True,
        text=True,
        check=True,
        timeout=60,
    ).stdout


def stop(process: NodeProcess) -> None:
    """Ctrl-C: the launch ends with its nodes, none with a traceback. Status 1 only where
    rviz2 died (a checkout without the 3D view, whose rviz2 says so in one line)."""
    code = process.interrupt()
    rviz2_died = "[ERROR] [rviz2-3]: process has died" in process.output
    assert code in ((0, 1, 130) if rviz2_died else (0, 130)), process.output[-4000:]
    assert "Traceback" not in process.output, process.output[-4000:]


@pytest.mark.parametrize("model", PAGES)
def test_display_launch_publishes_the_model_and_a_frame_for_every_link(
    model, node_process, executor
):
    robot = urdf.parse(expanded(model))
    frames = Frames(executor)
    launch = node_process(
        script("ros2"),
        "launch",
        "urdf_tutorial",
        "display.launch.py",
        f"model:={model}",
        env=ACTIVATED,
    )
    try:
        frames.until(lambda: frames.description is not None, "/robot_description")
        assert urdf.parse(frames.description).name == robot.name
        links = set(robot.links) - {robot.root}  # each has a frame, its joint's child
        frames.until(lambda: links <= set(frames.parents), f"frames for {sorted(links)}")
        for joint in robot.joints.values():
            assert frames.parents[joint.child] == joint.parent
            if joint.type == "fixed":  # where the page's <origin> puts it, on /tf_static
                t = frames.latest[joint.child].transform
                assert (t.translation.x, t.translation.y, t.translation.z) == pytest.approx(
                    joint.origin.xyz, abs=1e-9
                )
                assert (t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w) == pytest.approx(
                    joint.origin.rotation, abs=1e-9
                )
        if robot.moving_joints():  # the sliders' node publishes every movable joint
            frames.until(lambda: bool(frames.joint_states), "/joint_states")
            names = [joint.name for joint in robot.moving_joints()]
            assert list(frames.joint_states[-1].name) == names
        launch.wait_for_text("Open http://127.0.0.1:")  # the sliders page's link
    finally:
        stop(launch)


def r2d2_package(tmp_path: Path) -> Path:
    """The page's steps 1 to 6, typed as printed: the package, its urdf/ folder with the
    downloaded files, state_publisher.py, launch/demo_launch.py, the setup.py edits, then
    `colcon build --symlink-install --packages-select urdf_tutorial_r2d2`."""
    ok("mkdir -p second_ros2_ws/src", tmp_path)
    workspace = tmp_path / "second_ros2_ws"
    ok(
        activated(
            "cd second_ros2_ws/src\n"
            "ros2 pkg create --build-type ament_python --license Apache-2.0 urdf_tutorial_r2d2 "
            "--dependencies rclpy\n"
            "cd urdf_tutorial_r2d2\n"
            "mkdir -p urdf"
        ),
        tmp_path,
    )
    package = workspace / "src" / "urdf_tutorial_r2d2"
    for name in ("r2d2.urdf.xml", "r2d2.rviz"):  # the page's two downloads
        (package / "urdf" / name).write_text((R2D2 / name).read_text())
    (package / "urdf_tutorial_r2d2" / "state_publisher.py").write_text(
        (R2D2 / "state_publisher.py").read_text()
    )
    (package / "launch").mkdir()
    (package / "launch" / "demo_launch.py").write_text((R2D2 / "demo_launch.py").read_text())
    setup_py = package / "setup.py"
    text = setup_py.read_text()
    text = (
        "import os\nfrom glob import glob\nfrom setuptools import setup\n"
        "from setuptools import find_packages\n" + text
    )
    anchor = "('share/' + package_name, ['package.xml']),"
    assert anchor in text
    text = text.replace(
        anchor,
        anchor + "\n        (os.path.join('share', package_name, 'launch'), "
        "glob(os.path.join('launch', '*launch.[pxy][yma]*'))),\n"
        "        (os.path.join('share', package_name), glob('urdf/*')),",
    )
    setup_py.write_text(text)
    add_entry_points(setup_py, "state_publisher = urdf_tutorial_r2d2.state_publisher:main")
    built = ok(
        activated(
            "cd second_ros2_ws\ncolcon build --symlink-install --packages-select urdf_tutorial_r2d2"
        ),
        tmp_path,
        BUILD_TIMEOUT,
    )
    assert "Summary: 1 package finished" in built
    return workspace


def test_robot_state_publisher_page_r2d2_walks_in_a_circle(tmp_path, executor):
    workspace = r2d2_package(tmp_path)
    frames = Frames(executor)
    launch = terminal(workspace, "ros2 launch urdf_tutorial_r2d2 demo_launch.py")
    try:
        launch.wait_for_text("state_publisher started", timeout=LATE)
        frames.until(lambda: frames.description is not None, "/robot_description")
        assert urdf.parse(frames.description).name == "r2d2"
        fixed_and_moving = {"leg1", "leg2", "body", "head", "rod", "box"}
        frames.until(
            lambda: fixed_and_moving <= set(frames.parents) and "axis" in frames.latest,
            "a frame for every link, and odom -> axis",
        )
        assert frames.parents["axis"] == "odom"  # the page's odometry, on /tf
        assert frames.parents["head"] == "body"  # swivel, from the page's joint_states
        start = frames.latest["axis"].transform.translation
        start = (start.x, start.y)
        assert math.hypot(*start) == pytest.approx(2.0, abs=1e-6)  # on the circle of radius 2

        def walked() -> bool:
            now = frames.latest["axis"].transform.translation
            return math.dist((now.x, now.y), start) > 0.05

        frames.until(walked, "R2D2 walking along its circle")
        # 7 View the results, in a new terminal: the page's rviz2 command opens the 3D view.
        view = NodeProcess(
            prefix=[
                "bash",
                "-c",
                f"cd {shlex.quote(str(tmp_path))}\n"
                + activated(
                    "exec rviz2 -d second_ros2_ws/install/urdf_tutorial_r2d2/share/"
                    "urdf_tutorial_r2d2/r2d2.rviz --port 0"
                ),
                "bash",
            ],
            env=HEADLESS,
        )
        try:
            view.wait_for_text("in a browser (Ctrl-C to stop)")
        finally:
            view.interrupt()
        assert "error" not in view.output.lower(), view.output
    finally:
        page_stop(launch)


def test_xacro_page_typical_usage(tmp_path):
    """Using Xacro, "Typical usage": `xacro model.xacro > model.urdf` with the chapter's
    08-macroed.urdf.xacro; the result is the URDF the page describes (the macros expanded)."""
    (tmp_path / "model.xacro").write_text((MODELS / "08-macroed.urdf.xacro").read_text())
    ok(activated("xacro model.xacro > model.urdf"), tmp_path)
    made = (tmp_path / "model.urdf").read_text()
    robot = urdf.parse(made)
    assert robot.name == "macroed" and "xacro:" not in made
    assert {"right_leg", "left_leg", "right_front_wheel", "left_back_wheel"} <= set(robot.links)
    right = robot.joints["base_to_right_leg"].origin.xyz
    assert right == pytest.approx((0, 0.22, 0.25))  # the page's reflect*(width+.02)


def test_urdf_tutorial_is_installed_as_the_pages_name_it():
    share = run("ros2", "pkg", "prefix", "--share", "urdf_tutorial").stdout.strip()
    assert Path(share, "launch", "display.launch.py").is_file()
    assert Path(share, "rviz", "urdf.rviz").is_file()
    for mesh in ("l_finger.dae", "l_finger_tip.dae"):  # package://urdf_tutorial/meshes/...
        assert Path(share, "meshes", mesh).is_file()
    for model in PAGES:
        assert Path(share, model).is_file()
    shown = run("ros2", "launch", "urdf_tutorial", "display.launch.py", "--show-args").stdout
    for argument in ("'gui':", "'rvizconfig':", "'model':"):
        assert argument in shown, shown


def test_display_launch_without_the_sliders(node_process, executor):
    """`gui:=false`: joint_state_publisher instead of the sliders, every joint at its zero;
    a value outside the argument's choices is one line."""
    frames = Frames(executor)
    launch = node_process(
        script("ros2"),
        "launch",
        "urdf_tutorial",
        "display.launch.py",
        "model:=urdf/06-flexible.urdf",
        "gui:=false",
        env=ACTIVATED,
    )
    try:
        frames.until(lambda: bool(frames.joint_states), "/joint_states")
        assert set(frames.joint_states[-1].position) == {0.0}
        frames.until(lambda: "head" in frames.latest, "the head's frame on /tf")
        assert "[joint_state_publisher-2]: process started" in launch.output
    finally:
        stop(launch)
    assert "joint_state_publisher_gui" not in launch.output
    refused = run("ros2", "launch", "urdf_tutorial", "display.launch.py", "gui:=maybe")
    assert refused.returncode == 1
    assert refused.stderr.strip().endswith(
        "argument 'gui' is 'maybe'; choose one of ['true', 'false']"
    )
