"""Packages and the ament index: AMENT_PREFIX_PATH (default and user set), the lessons'
registration, `rospack find`, `rosmsg show` and the launcher's $(find-pkg-share),
$(find-pkg-prefix) and $(find) answering from the index.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import TIMEOUT, finished

from launcher import LaunchError
from launcher.loading import resolve
from launcher.plan import make_plan
from launcher.scope import Options
from ros_tutorials_common import ament, packages

ROOT = Path(__file__).resolve().parent.parent
VENV_SHARE = Path(sys.prefix) / "share"
LESSONS = sorted(path.parent.name for path in ROOT.glob("ros_tutorials_*/package.xml"))
STAND_INS = [path.parent.name for path in ROOT.glob("*/package.xml")
             if not path.parent.name.startswith("ros_tutorials_")]  # fmt: skip


def run_tool(args: list[str], ament_prefix_path: str | None) -> subprocess.CompletedProcess:
    """A console script of this project with AMENT_PREFIX_PATH set to a value, or unset."""
    env = dict(os.environ)
    env.pop(ament.PREFIX_PATH, None)
    if ament_prefix_path is not None:
        env[ament.PREFIX_PATH] = ament_prefix_path
    return finished(*args, env=env)


def test_this_environment_is_the_default_prefix_and_comes_after_the_users():
    here = sys.prefix
    assert ament.apply_ament_defaults({}) == {"AMENT_PREFIX_PATH": here}
    user = {"AMENT_PREFIX_PATH": f"/ws/install{os.pathsep}{os.pathsep}/opt/other"}
    expected = os.pathsep.join(["/ws/install", "/opt/other", here])
    assert ament.apply_ament_defaults(user)["AMENT_PREFIX_PATH"] == expected
    already = {"AMENT_PREFIX_PATH": f"{here}{os.pathsep}/ws/install"}  # the user's order stays
    assert ament.apply_ament_defaults(dict(already)) == already


def test_lookups_read_the_wheels_index_in_this_environment():
    found = ament.packages()
    assert found["std_msgs"] == found["rclpy"] == Path(sys.prefix)
    assert ament.share_directory("std_msgs") == VENV_SHARE / "std_msgs"
    assert sys.prefix in os.environ["AMENT_PREFIX_PATH"].split(os.pathsep)
    assert "msg/String.msg" in ament.resource("rosidl_interfaces", "std_msgs").split()
    for bad in ("nope_not_here", "a/b", "x"):
        with pytest.raises(ament.PackageNotFound, match="in the ament index"):
            ament.package_prefix(bad)


def test_make_setup_registered_each_lesson_package_as_a_symlink_install():
    assert {"ros_tutorials_topic", "ros_tutorials_turtlesim"} <= set(LESSONS)
    index = ament.packages()
    for name in LESSONS:
        assert index.get(name) == Path(sys.prefix), f"{name} is not in the ament index"
        share = VENV_SHARE / name
        assert (share / "package.xml").resolve() == ROOT / name / "package.xml"
        if (ROOT / name / "launch").is_dir():
            assert (share / "launch").resolve() == ROOT / name / "launch"
        assert f"<name>{name}</name>" in (share / "package.xml").read_text()
    # The interface packages (installed by CMake) lead back to their sources too.
    for name in ("ros_tutorials_interfaces", "turtlesim"):
        assert packages.package_folder(name) == ROOT / "interfaces" / name
    assert set(LESSONS) - {"ros_tutorials_interfaces"} <= set(packages.runnable_packages())


def test_launch_file_substitutions_answer_from_the_index(tmp_path):
    share = VENV_SHARE / "ros_tutorials_turtlesim"
    include = tmp_path / "top.launch.xml"
    include.write_text(
        "<launch>\n"
        '<include file="$(find-pkg-share ros_tutorials_turtlesim)/launch/multisim.launch.xml"/>\n'
        '<node pkg="ros_tutorials_topic" exec="talker" name="t" args="$(find-pkg-prefix pub_sub)'
        ' $(find-pkg-share turtlesim) $(find-pkg-share my_package/x)"/>\n'
        "</launch>\n"
    )
    with pytest.raises(LaunchError, match=r"top.launch.xml:3: unknown package 'my_package/x'"):
        make_plan(resolve(include, {}, Options()))
    include.write_text(include.read_text().replace(" $(find-pkg-share my_package/x)", ""))
    *turtles, talker = make_plan(resolve(include, {}, Options()))
    assert {spec.label for spec in turtles} >= {"turtlesim1/sim", "turtlesim2/sim"}
    assert talker.command[4:6] == [sys.prefix, str(VENV_SHARE / "turtlesim")]
    assert (share / "launch" / "multisim.launch.xml").is_file()

    ros1 = tmp_path / "top.launch"
    ros1.write_text(
        '<launch><node pkg="ros_tutorials_topic" type="talker" name="t"'
        ' args="$(find ros_tutorials_parameter) $(find pub_sub) $(find std_msgs)"/></launch>'
    )
    (talker,) = make_plan(resolve(ros1, {}, Options()))
    expected = [str(ROOT / "ros_tutorials_parameter"), str(ROOT / "ros_tutorials_topic")]
    assert talker.command[4:7] == [*expected, str(VENV_SHARE / "std_msgs")]


def make_overlay(prefix: Path) -> None:
    """An install prefix of the user's: a package with one message, and a ros_tutorials_topic
    whose share/ shadows this environment's."""
    index = prefix / "share" / "ament_index" / "resource_index"
    for resource in ("packages", "rosidl_interfaces"):
        (index / resource).mkdir(parents=True)
    (index / "packages" / "overlay_msgs").touch()
    (index / "rosidl_interfaces" / "overlay_msgs").write_text("msg/Reading.msg\n")
    (prefix / "share" / "overlay_msgs" / "msg").mkdir(parents=True)
    (prefix / "share" / "overlay_msgs" / "msg" / "Reading.msg").write_text("float64 value\n")
    (index / "packages" / "ros_tutorials_topic").touch()
    (prefix / "share" / "ros_tutorials_topic" / "launch").mkdir(parents=True)


def test_a_user_set_prefix_path_is_searched_first_and_this_environment_after_it(tmp_path):
    overlay = tmp_path / "install"
    make_overlay(overlay)
    user_set = os.pathsep.join([str(overlay), str(tmp_path / "missing")])
    result = run_tool(["rospack", "find", "overlay_msgs"], user_set)
    assert (result.returncode, result.stdout) == (0, f"{overlay / 'share' / 'overlay_msgs'}\n")
    shadowed = run_tool(["rospack", "find", "ros_tutorials_topic"], user_set).stdout
    assert shadowed == f"{overlay / 'share' / 'ros_tutorials_topic'}\n"  # the overlay wins
    assert run_tool(["rospack", "find", "std_msgs"], user_set).stdout == f"{VENV_SHARE}/std_msgs\n"
    assert (
        run_tool(["rosmsg", "show", "overlay_msgs/Reading"], user_set).stdout == "float64 value\n"
    )
    listed = run_tool(["ros2", "interface", "packages"], user_set).stdout.split()
    assert "overlay_msgs" in listed and "std_msgs" in listed

    # Unset, or set to nothing: this environment alone.
    for unset in (None, ""):
        result = run_tool(["rospack", "find", "ros_tutorials_topic"], unset)
        assert result.stdout == f"{ROOT / 'ros_tutorials_topic'}\n"
        result = run_tool(["rosmsg", "show", "overlay_msgs/Reading"], unset)
        assert result.returncode == 1 and "no interface package 'overlay_msgs'" in result.stderr


def test_register_packages_writes_the_index_and_removes_what_it_registered_before(tmp_path):
    tool = [sys.executable, str(ROOT / "tools" / "register_packages.py"), "--prefix", str(tmp_path)]
    index = tmp_path / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True)
    # A package registered from a folder of this project that is gone, and one of another project.
    gone = tmp_path / "share" / "ros_tutorials_gone"
    gone.mkdir()
    (gone / "package.xml").symlink_to(ROOT / "ros_tutorials_gone" / "package.xml")
    (index / "ros_tutorials_gone").touch()
    (tmp_path / "share" / "other").mkdir()
    (tmp_path / "share" / "other" / "package.xml").write_text("<package/>")
    (index / "other").touch()
    for _ in range(2):  # a second run changes nothing
        result = subprocess.run(tool, capture_output=True, text=True, timeout=TIMEOUT)
        assert result.returncode == 0, result.stderr
        registered = sorted(path.name for path in index.iterdir())
        # ament_copyright, rosbag2_py, tf2_ros ...: ROS packages PyPI lacks, this project's own
        assert registered == sorted([*LESSONS, *STAND_INS, "other"])
        assert {"ament_copyright", "rosbag2_py"} <= set(STAND_INS)
    assert not gone.exists() and (tmp_path / "share" / "other" / "package.xml").is_file()
    launch = tmp_path / "share" / "ros_tutorials_topic" / "launch"
    assert launch.is_symlink() and (launch / "union.launch").is_file()


def test_the_launcher_passes_the_prefix_path_on_to_its_processes(tmp_path, node_process):
    show = tmp_path / "show.py"
    show.write_text("import os\nprint('AMENT_PREFIX_PATH=' + os.environ['AMENT_PREFIX_PATH'])\n")
    launch = tmp_path / "show.launch.xml"
    launch.write_text(
        f'<launch><executable cmd="{sys.executable} {show}" name="show" output="screen"/></launch>'
    )
    launcher = node_process("-m", "launcher", str(launch), env={"AMENT_PREFIX_PATH": str(tmp_path)})
    expected = f"AMENT_PREFIX_PATH={tmp_path}{os.pathsep}{sys.prefix}"  # the user's, then here
    launcher.wait_for_output(
        lambda lines: any(line.endswith(expected) for line in lines), what=f"'{expected}'"
    )
