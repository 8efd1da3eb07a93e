"""The URDF reader robot_state_publisher and joint_state_publisher share
(ros_tutorials_common/urdf.py): the chapter's models, the joint poses KDL computes, and the
descriptions urdfdom refuses, each refused in one line."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import pytest

from ros_tutorials_common import quaternion, urdf

MODELS = Path(__file__).resolve().parents[1] / "urdf_tutorial" / "urdf"
XACRO = str(Path(sys.executable).parent / "xacro")


def model(name: str) -> urdf.Robot:
    if name.endswith(".xacro"):
        text = subprocess.run(
            [XACRO, str(MODELS / name)], capture_output=True, text=True, check=True, timeout=60
        ).stdout
    else:
        text = (MODELS / name).read_text()
    return urdf.parse(text)


def close(a, b) -> bool:
    return all(math.isclose(x, y, abs_tol=1e-6) for x, y in zip(a, b, strict=True))


@pytest.mark.parametrize(
    ("name", "robot", "links", "moving"),
    [
        ("01-myfirst.urdf", "myfirst", 1, []),
        ("02-multipleshapes.urdf", "multipleshapes", 2, []),
        ("03-origins.urdf", "origins", 2, []),
        ("04-materials.urdf", "materials", 3, []),
        ("05-visual.urdf", "visual", 16, []),
        ("06-flexible.urdf", "flexible", 16, ["gripper_extension", "head_swivel"]),
        ("07-physics.urdf", "physics", 16, ["gripper_extension", "head_swivel"]),
        ("08-macroed.urdf.xacro", "macroed", 16, ["gripper_extension", "head_swivel"]),
    ],
)
def test_the_chapters_models_are_trees_rooted_at_base_link(name, robot, links, moving):
    read = model(name)
    assert (read.name, read.root, len(read.links)) == (robot, "base_link", links)
    names = {joint.name for joint in read.moving_joints()}
    assert set(moving) <= names
    if moving:  # the movable page's joints: 4 wheels, 2 grippers, the arm and the head
        assert len(names) == 8
        assert read.joints["head_swivel"].type == "continuous"
        assert read.joints["left_gripper_joint"].type == "revolute"
        gripper = read.joints["gripper_extension"]
        assert (gripper.type, gripper.lower, gripper.upper) == ("prismatic", -0.38, 0.0)


def test_joint_poses_are_the_origin_then_the_motion():
    robot = model("06-flexible.urdf")
    leg = robot.joints["base_to_right_leg"].pose()
    assert close(leg.xyz, (0, -0.22, 0.25)) and close(leg.rotation, (0, 0, 0, 1))
    head = robot.joints["head_swivel"].pose(math.pi / 2)  # a quarter turn about z
    assert close(head.xyz, (0, 0, 0.3))
    assert close(head.rotation, (0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4)))
    arm = robot.joints["gripper_extension"].pose(-0.2)  # slides along x (the default axis)
    assert close(arm.xyz, (-0.01, 0, 0.2))
    wheel = robot.joints["right_front_wheel_joint"].pose(math.pi)  # half a turn about y
    assert close(wheel.rotation, (0, 1, 0, 0))


def test_rpy_is_fixed_axes_roll_pitch_yaw():
    q = quaternion.quaternion_from_rpy(0.1, 0.2, 0.3)
    expected = quaternion.multiply(
        quaternion.multiply(
            quaternion.quaternion_from_rpy(0, 0, 0.3), quaternion.quaternion_from_rpy(0, 0.2, 0)
        ),
        quaternion.quaternion_from_rpy(0.1, 0, 0),
    )
    assert close(q, expected)
    assert close(
        quaternion.rotate(quaternion.quaternion_from_rpy(0, 0, math.pi / 2), (1, 0, 0)), (0, 1, 0)
    )


LINK = '<link name="{}"/>'
JOINT = '<joint name="{}" type="{}"><parent link="{}"/><child link="{}"/>{}</joint>'


@pytest.mark.parametrize(
    ("text", "error"),
    [
        ("", "the robot description is empty"),
        ("<robot name='r'><link name='a'>", "not valid XML: no element found: line 1"),
        ("<robo name='r'/>", "Could not find the 'robot' element in the xml file"),
        ("<robot><link name='a'/></robot>", "No name given for the robot."),
        ("<robot name='r'/>", "No link elements found in urdf file"),
        ("<robot name='r'><link name='a'/><link name='a'/></robot>", "link 'a' is not unique."),
        (
            "<robot name='r'>" + LINK.format("a") + LINK.format("b") + "</robot>",
            "Two root links found: [a] and [b]",
        ),
        (
            "<robot name='r'>"
            + LINK.format("a")
            + JOINT.format("j", "hinge", "a", "a", "")
            + "</robot>",
            "Joint [j] has no known type [hinge]",
        ),
        (
            "<robot name='r'>"
            + LINK.format("a")
            + JOINT.format("j", "fixed", "a", "b", "")
            + "</robot>",
            "child link [b] of joint [j] not found",
        ),
        (
            "<robot name='r'>"
            + LINK.format("a")
            + LINK.format("b")
            + JOINT.format("j", "revolute", "a", "b", "")
            + "</robot>",
            "Joint [j] is of type REVOLUTE but it does not specify limits",
        ),
        (
            "<robot name='r'>"
            + LINK.format("a")
            + LINK.format("b")
            + JOINT.format("j", "fixed", "a", "b", '<origin xyz="0 one 0"/>')
            + "</robot>",
            "joint [j]: origin xyz must be 3 numbers, not '0 one 0'",
        ),
        (
            "<robot name='r'>"
            + LINK.format("a")
            + LINK.format("b")
            + LINK.format("c")
            + JOINT.format("j", "fixed", "b", "c", "")
            + JOINT.format("k", "fixed", "c", "b", "")
            + "</robot>",
            "link [b] is in a loop of joints: a URDF must be a tree",
        ),
        (
            '<?xml version="1.0"?><!DOCTYPE r [<!ENTITY a "aaaa">]><robot name="&a;"/>',
            "a DOCTYPE (DTD) is not allowed in a robot description",
        ),
        (
            "<robot name='r'>" + "<link name='a'/>" * 10 + "x" * urdf.MAX_URDF_BYTES,
            "the robot description is larger than 8 MiB",
        ),
    ],
)
def test_a_malformed_description_is_one_line(text, error):
    with pytest.raises(urdf.UrdfError) as refused:
        urdf.parse(text)
    assert str(refused.value).startswith(error)
    assert "\n" not in str(refused.value)
