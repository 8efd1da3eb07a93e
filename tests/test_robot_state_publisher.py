"""robot_state_publisher and joint_state_publisher as ROS 2 Jazzy's, run as real processes:
the URDF republished on /robot_description (transient local), fixed joints on /tf_static,
/joint_states turned into /tf, frame_prefix, a new robot_description set while running, the
movable joints on /joint_states, and a malformed or missing URDF as one line."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from helpers import NodeProcess, run, script, spin_until
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from sensor_msgs.msg import JointState
from std_msgs.msg import String
from tf2_msgs.msg import TFMessage

MODELS = Path(__file__).resolve().parents[1] / "urdf_tutorial" / "urdf"
FLEXIBLE = MODELS / "06-flexible.urdf"
HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
# The movable joints of 06-flexible.urdf in the file's order.
FLEXIBLE_JOINTS = [
    "right_front_wheel_joint",
    "right_back_wheel_joint",
    "left_front_wheel_joint",
    "left_back_wheel_joint",
    "gripper_extension",
    "left_gripper_joint",
    "right_gripper_joint",
    "head_swivel",
]


class Watcher:
    """The test's node: /robot_description, /tf_static, /tf and /joint_states as they come."""

    def __init__(self, executor) -> None:
        self.executor = executor
        self.node = Node("urdf_watcher", context=executor.context)
        executor.add_node(self.node)
        self.description: str | None = None
        self.static: dict[str, object] = {}  # child frame -> transform
        self.moving: dict[str, object] = {}
        self.joint_states: list[JointState] = []
        self.node.create_subscription(String, "/robot_description", self._description, LATCHED)
        static_qos = QoSProfile(depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.node.create_subscription(TFMessage, "/tf_static", self._static, static_qos)
        self.node.create_subscription(TFMessage, "/tf", self._moving, 100)
        self.node.create_subscription(JointState, "/joint_states", self.joint_states.append, 10)
        self.joints = self.node.create_publisher(JointState, "/joint_states", 10)

    def _description(self, msg: String) -> None:
        self.description = msg.data

    def _static(self, msg: TFMessage) -> None:
        self.static.update({t.child_frame_id: t for t in msg.transforms})

    def _moving(self, msg: TFMessage) -> None:
        self.moving.update({t.child_frame_id: t for t in msg.transforms})

    def until(self, condition, what: str) -> None:
        spin_until(self.executor, condition, what=what)

    def move(self, **positions: float) -> None:
        state = JointState(name=list(positions), position=list(positions.values()))
        state.header.stamp = self.node.get_clock().now().to_msg()
        self.joints.publish(state)


def params_file(tmp_path: Path, node: str, **values: str) -> str:
    """A parameters file as a learner writes one: the URDF as a YAML block scalar."""
    lines = [f"{node}:", "  ros__parameters:"]
    for name, text in values.items():
        lines.append(f"    {name}: |")
        lines += [f"      {line}" for line in text.splitlines()]
    path = tmp_path / "params.yaml"
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def ros2_run(node_process, *args: str) -> NodeProcess:
    return node_process(script("ros2"), "run", *args, env=HEADLESS)


def vector(t) -> tuple[float, float, float]:
    v = t.transform.translation
    return (v.x, v.y, v.z)


def quaternion(t) -> tuple[float, float, float, float]:
    q = t.transform.rotation
    return (q.x, q.y, q.z, q.w)


def close(a, b) -> bool:
    return all(math.isclose(x, y, abs_tol=1e-6) for x, y in zip(a, b, strict=True))


def test_robot_state_publisher_publishes_the_robot_and_its_frames(node_process, executor, tmp_path):
    watcher = Watcher(executor)
    description = FLEXIBLE.read_text()
    rsp = ros2_run(
        node_process,
        "robot_state_publisher",
        "robot_state_publisher",
        "--ros-args",
        "--params-file",
        params_file(tmp_path, "robot_state_publisher", robot_description=description),
    )
    rsp.wait_for_text("Robot initialized")
    watcher.until(lambda: watcher.description is not None, "/robot_description")
    assert watcher.description.strip() == description.strip()
    # Every fixed joint on /tf_static, latched: legs, bases, fingertips, the box.
    fixed = {"right_leg", "right_base", "left_leg", "left_base", "left_tip", "right_tip", "box"}
    watcher.until(lambda: fixed <= set(watcher.static), "the fixed joints on /tf_static")
    leg = watcher.static["right_leg"]
    assert (leg.header.frame_id, vector(leg)) == ("base_link", pytest.approx((0, -0.22, 0.25)))
    assert not set(watcher.static) & {"head", "gripper_pole"}  # moving joints: not static

    # /joint_states -> /tf, each moving joint at its position.
    def moved() -> bool:
        head, pole = watcher.moving.get("head"), watcher.moving.get("gripper_pole")
        return (
            head is not None
            and pole is not None
            and close(quaternion(head), (0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4)))
            and close(vector(pole), (-0.01, 0, 0.2))
        )

    spin_until(
        executor,
        lambda: watcher.move(head_swivel=math.pi / 2, gripper_extension=-0.2) or moved(),
        what="the head turned a quarter and the arm out on /tf",
    )
    assert watcher.moving["head"].header.frame_id == "base_link"

    # frame_prefix, set while it runs: the next transforms carry it.
    assert run("ros2", "param", "set", "/robot_state_publisher", "frame_prefix", "r2/").stdout == (
        "Set parameter successful\n"
    )
    spin_until(
        executor,
        lambda: watcher.move(head_swivel=0.0) or "r2/head" in watcher.moving,
        what="r2/head on /tf",
    )
    assert watcher.moving["r2/head"].header.frame_id == "r2/base_link"

    # A malformed robot_description is refused in one line; a new robot replaces the old one.
    refused = run("ros2", "param", "set", "/robot_state_publisher", "robot_description", "<r")
    assert refused.stderr.startswith("Setting parameter failed: Unable to initialize urdf::model")
    tiny = '<robot name="tiny"><link name="base_link"/></robot>'
    replaced = run("ros2", "param", "set", "/robot_state_publisher", "robot_description", tiny)
    assert replaced.stdout == "Set parameter successful\n"
    watcher.until(lambda: watcher.description == tiny, "the new robot on /robot_description")
    assert rsp.interrupt() in (0, 130)
    assert "Traceback" not in rsp.output


def test_joint_state_publisher_publishes_every_movable_joint(node_process, executor):
    watcher = Watcher(executor)
    jsp = ros2_run(
        node_process,
        "joint_state_publisher",
        "joint_state_publisher",
        str(FLEXIBLE),
        "--ros-args",
        "-p",
        "zeros.head_swivel:=0.5",
    )
    watcher.until(lambda: len(watcher.joint_states) >= 2, "two messages on /joint_states")
    state = watcher.joint_states[-1]
    assert list(state.name) == FLEXIBLE_JOINTS
    positions = dict(zip(state.name, state.position, strict=True))
    assert positions["head_swivel"] == pytest.approx(0.5)  # zeros.head_swivel
    assert positions["gripper_extension"] == 0.0  # 0 is within -0.38..0
    assert (list(state.velocity), list(state.effort)) == ([], [])  # not asked for
    assert jsp.interrupt() in (0, 130)
    assert "Traceback" not in jsp.output


def test_joint_state_publisher_waits_for_robot_description(node_process, executor, tmp_path):
    """Given no file, it takes the robot robot_state_publisher publishes (the launch files')."""
    watcher = Watcher(executor)
    jsp = ros2_run(node_process, "joint_state_publisher", "joint_state_publisher")
    jsp.wait_for_text("Waiting for robot_description to be published on the robot_description")
    ros2_run(
        node_process,
        "robot_state_publisher",
        "robot_state_publisher",
        "--ros-args",
        "--params-file",
        params_file(tmp_path, "robot_state_publisher", robot_description=FLEXIBLE.read_text()),
    )
    watcher.until(
        lambda: (
            bool(watcher.joint_states) and list(watcher.joint_states[-1].name) == FLEXIBLE_JOINTS
        ),
        "/joint_states naming 06-flexible's joints",
    )
    # ... and robot_state_publisher turns them into /tf: every link has a frame.
    watcher.until(lambda: "head" in watcher.moving, "the head's frame on /tf")


@pytest.mark.parametrize(
    ("args", "line"),
    [
        ((), "robot_description parameter must not be empty"),
        (
            ("--ros-args", "-p", "robot_description:=<robot name='r'><link name='a'>"),
            "Unable to initialize urdf::model from robot description: not valid XML: ",
        ),
        (
            ("--ros-args", "-p", "robot_description:=<robot name='r'/>"),
            "Unable to initialize urdf::model from robot description: No link elements found",
        ),
        (("--ros-args", "-p", "robot_description:=7"), "robot_description must be a string"),
        (("/no/such/file.urdf",), "Failed to open URDF file: cannot read /no/such/file.urdf"),
    ],
)
def test_robot_state_publisher_refuses_a_bad_description_in_one_line(args, line):
    result = run("ros2", "run", "robot_state_publisher", "robot_state_publisher", *args)
    assert result.returncode == 1
    output = (result.stdout + result.stderr).strip().splitlines()
    fatal = [text for text in output if "[FATAL]" in text]
    assert len(fatal) == 1 and f"[robot_state_publisher]: {line}" in fatal[0], output
    assert "Traceback" not in result.stderr


def test_joint_state_publisher_refuses_a_malformed_file_in_one_line(tmp_path):
    broken = tmp_path / "broken.urdf"
    broken.write_text("<robot name='r'><link name='a'/><joint name='j' type='revolute'>")
    result = run("ros2", "run", "joint_state_publisher", "joint_state_publisher", str(broken))
    assert result.returncode == 1
    output = (result.stdout + result.stderr).strip().splitlines()
    assert len(output) == 1 and "[FATAL]" in output[0] and "not valid XML" in output[0], output


def test_robot_state_publisher_reads_a_file_argument_with_upstreams_warning(node_process, executor):
    """No robot_description, a URDF file as the first argument: ROS 2's old fallback, with its
    warning; the file's robot is published as if it had been the parameter."""
    watcher = Watcher(executor)
    first = MODELS / "01-myfirst.urdf"
    rsp = ros2_run(node_process, "robot_state_publisher", "robot_state_publisher", str(first))
    rsp.wait_for_text("Robot initialized")
    assert "No robot_description parameter, but command-line argument available." in rsp.output
    watcher.until(lambda: watcher.description is not None, "/robot_description")
    assert watcher.description == first.read_text()
    assert rsp.interrupt() in (0, 130)


def test_ignore_timestamp_takes_joint_states_without_a_stamp(node_process, executor, tmp_path):
    """A JointState with no stamp is older than any publish interval: robot_state_publisher
    ignores it, as ROS 2's does, unless ignore_timestamp is true."""
    watcher = Watcher(executor)
    path = params_file(tmp_path, "robot_state_publisher", robot_description=FLEXIBLE.read_text())
    with open(path, "a") as params:
        params.write("    ignore_timestamp: true\n")
    ros2_run(
        node_process,
        "robot_state_publisher",
        "robot_state_publisher",
        "--ros-args",
        "--params-file",
        path,
    ).wait_for_text("Robot initialized")
    unstamped = JointState(name=["head_swivel"], position=[1.0])
    spin_until(
        executor,
        lambda: watcher.joints.publish(unstamped) or "head" in watcher.moving,
        what="the head's frame from an unstamped JointState",
    )
    assert watcher.moving["head"].header.stamp.sec == 0


MIMIC = """<robot name="pincer">
  <link name="base"/><link name="left"/><link name="right"/>
  <joint name="left_finger" type="revolute"><parent link="base"/><child link="left"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="right_finger" type="revolute"><parent link="base"/><child link="right"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>
    <mimic joint="left_finger" multiplier="-1" offset="0.1"/></joint>
</robot>
"""


def test_source_list_and_mimic_joints(node_process, executor, tmp_path):
    """joint_state_publisher takes a joint's value from a source_list topic and publishes the
    joint that mimics it (multiplier, offset); robot_state_publisher turns both into /tf."""
    watcher = Watcher(executor)
    # robot_state_publisher first: joint_state_publisher, given no file, takes its robot from
    # /robot_description once (a robot published later would start its joints over at zero).
    rsp = ros2_run(
        node_process,
        "robot_state_publisher",
        "robot_state_publisher",
        "--ros-args",
        "--params-file",
        params_file(tmp_path, "robot_state_publisher", robot_description=MIMIC),
    )
    rsp.wait_for_text("Robot initialized")
    ros2_run(
        node_process,
        "joint_state_publisher",
        "joint_state_publisher",
        "--ros-args",
        "-p",
        "source_list:=['/hand']",
    )
    hand = watcher.node.create_publisher(JointState, "/hand", 10)

    def follows() -> bool:
        hand.publish(JointState(name=["left_finger"], position=[0.5]))
        if not watcher.joint_states:
            return False
        state = watcher.joint_states[-1]
        return dict(zip(state.name, state.position, strict=True)).get("left_finger") == 0.5

    spin_until(executor, follows, what="left_finger at 0.5 from /hand on /joint_states")
    state = watcher.joint_states[-1]
    assert list(state.name) == ["left_finger", "right_finger"]
    assert state.position[1] == pytest.approx(-0.5 + 0.1)  # the mimic: -1 * 0.5 + 0.1

    def turned(frame: str, angle: float) -> bool:
        t = watcher.moving.get(frame)
        return t is not None and close(
            quaternion(t), (0, 0, math.sin(angle / 2), math.cos(angle / 2))
        )

    spin_until(
        executor,
        lambda: turned("left", 0.5) and turned("right", -0.4),
        what="both fingers' frames on /tf",
    )
