"""The package index's answers (ros_tutorials_common/packages.py): which (package, executable)
pairs exist, for `ros2 run`, `rosrun`, the launcher and `ros2 pkg` alike; xacro, from PyPI, found
as a ROS installation has it; and `$(eval)` refusing a value too big before it computes it."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import fails, ok

from launch_foundation.expressions import BUILTINS, MATH, evaluate
from ros2cmd.pkg import api as pkg
from ros_tutorials_common import ament, packages


def every_package_name() -> list[str]:
    """The names `ros2 run` takes: the runnable packages, and the seeds' names for them."""
    seeds = [name for name in packages.PACKAGE_ALIASES if packages.resolve_package(name)]
    return sorted({*packages.runnable_packages(), *seeds})


@pytest.mark.parametrize("name", every_package_name())
def test_ros2_pkg_lists_exactly_what_ros2_run_runs(name):
    listed = pkg.executables(name)
    assert listed, f"`ros2 pkg executables {name}` lists nothing"
    table = packages.executable_commands(name)
    for executable, path in listed.items():
        assert packages.command(name, executable) == table[executable]
        assert path.is_file(), (name, executable, path)
    # Every program `ros2 run` starts is listed, under one of its names.
    assert {tuple(line) for line in table.values()} == {
        tuple(table[executable]) for executable in listed
    }


def test_ros2_pkg_executables_of_the_seeds_names():
    # ros2 run demo_nodes_cpp talker works here, so `ros2 pkg` names it too.
    assert "demo_nodes_cpp talker\n" in ok("ros2", "pkg", "executables", "demo_nodes_cpp")
    share = ok("ros2", "pkg", "prefix", "--share", "demo_nodes_cpp").strip()
    assert share == str(packages.share_directory("ros_tutorials_demo_nodes"))
    assert fails("ros2", "pkg", "prefix", "my_package").startswith(
        "error: my_package (a seed's package) stands for ros_tutorials_topic, "
    )
    # Seed 003's own names, for the lessons they run here.
    listed = ok("ros2", "pkg", "executables", "pub_sub").splitlines()
    assert {"pub_sub publisher", "pub_sub subscriber"} <= set(listed)
    assert packages.command("pub_sub", "publisher") == packages.command(
        "ros_tutorials_topic", "num_publisher"
    )


def test_an_executable_named_with_its_suffix_is_looked_up_by_that_name_first():
    table = packages.executable_commands("rospy_tutorials")
    # ROS 1 launch files name scripts with their suffix; here they have none.
    assert packages.command("rospy_tutorials", "listener.py") == table["listener"]
    with pytest.raises(packages.UnknownExecutable, match=re.escape("no executable 'nothing.py'")):
        packages.command("rospy_tutorials", "nothing.py")


def test_a_stand_ins_executables_are_its_modules_with_a_main(tmp_path, monkeypatch):
    # A stand-in as tools/register_packages.py registers one: share/PKG/package.xml links to
    # the package.xml beside its Python code (here in a prefix of its own, put first).
    source = tmp_path / "src" / "tf2_stand_in"
    source.mkdir(parents=True)
    (source / "package.xml").write_text("<package format='3'><name>tf2_stand_in</name></package>")
    (source / "__init__.py").write_text("")
    (source / "echo.py").write_text("def main():\n    return 0\n")
    (source / "buffer.py").write_text("class Buffer:\n    pass\n")  # a library module
    (source / "main.py").write_text("def main():\n    return 0\n")
    prefix = tmp_path / "prefix"
    (prefix / "share" / "tf2_stand_in").mkdir(parents=True)
    (prefix / "share" / "tf2_stand_in" / "package.xml").symlink_to(source / "package.xml")
    index = prefix / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True)
    (index / "tf2_stand_in").touch()
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(prefix))
    monkeypatch.syspath_prepend(str(source.parent))
    monkeypatch.setattr(packages, "console_scripts", lambda: {"stand_in": "tf2_stand_in.main:main"})
    for cached in (packages.package_dirs, packages.executables):
        cached.cache_clear()
    try:
        assert packages.stand_in("tf2_stand_in") and not packages.stand_in("ros_tutorials_topic")
        # main.py is what its console script runs: a command on PATH, not `ros2 run`'s.
        assert packages.executable_commands("tf2_stand_in") == {
            "echo": [sys.executable, "-m", "tf2_stand_in.echo"]
        }
        assert "tf2_stand_in" in packages.runnable_packages()
    finally:
        for cached in (packages.package_dirs, packages.executables):
            cached.cache_clear()


def test_the_stand_ins_console_scripts_stay_commands_on_path():
    # ament_copyright's `ament_copyright` is on PATH (ROS installs it in bin/), not ros2 run's.
    assert packages.stand_in("ament_copyright")
    assert packages.executable_commands("ament_copyright") == {}
    assert "ros_tutorials_topic" in packages.package_dirs()
    assert "turtlesim" not in packages.package_dirs()  # an interface package, not a stand-in


# -- xacro -------------------------------------------------------------------------------------

ROBOT_XACRO = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="box_bot">
  <xacro:property name="side" value="0.5"/>
  <xacro:macro name="box_link" params="name">
    <link name="${name}"><visual><geometry><box size="${side} ${side*2} 1"/></geometry></visual>
    </link>
  </xacro:macro>
  <xacro:box_link name="base_link"/>
</robot>
"""


def test_xacro_turns_a_xacro_file_into_urdf(tmp_path):
    source = tmp_path / "box_bot.urdf.xacro"
    source.write_text(ROBOT_XACRO)
    urdf = ok("xacro", str(source))
    assert '<robot name="box_bot">' in urdf
    assert '<link name="base_link">' in urdf and '<box size="0.5 1.0 1"/>' in urdf
    # As a ROS installation has it: `ros2 run xacro xacro` and ROS 1's `$(find xacro)/xacro`.
    assert ok("ros2", "run", "xacro", "xacro", str(source)) == urdf
    assert "xacro" in ament.packages()
    found = Path(ok("rospack", "find", "xacro").strip())
    assert found == ament.share_directory("xacro")
    result = subprocess.run(
        [str(found / "xacro"), str(source)], capture_output=True, text=True, timeout=60
    )
    assert result.returncode == 0 and result.stdout == urdf, result.stderr
    assert ok("ros2", "pkg", "executables", "xacro") == "xacro xacro\n"


# -- $(eval) ------------------------------------------------------------------------------------

TOO_BIG = [
    "[[1]*1000000]*1000000 == [[1]*1000000]*1000000",
    "str([[1]*1000000]*1000000)",
    "'%0999999999d' % 1",
    "'%*d' % (999999999, 1)",
    "str([10**1000]*100000)",
    "round(10, -10**18)",
]


@pytest.mark.parametrize("expression", TOO_BIG)
def test_eval_refuses_a_value_too_big_before_computing_it(expression):
    with pytest.raises(OverflowError):
        evaluate(expression, {**MATH, **BUILTINS})


@pytest.mark.parametrize(
    "expression,value",
    [("'%05d' % 42", "00042"), ("'%s-%.2f' % ('a', 2)", "a-2.00"), ("len([0]*1000)", 1000),
     ("round(1234, -2)", 1200), ("[1, 2] * 2 == [1, 2, 1, 2]", True)],
)  # fmt: skip
def test_eval_still_computes_what_is_small(expression, value):
    assert evaluate(expression, {**MATH, **BUILTINS}) == value


def test_a_launch_file_with_a_huge_eval_fails_in_one_line(tmp_path):
    path = tmp_path / "big.launch"
    path.write_text(
        '<launch><arg name="x" value="$(eval [[1]*1000000]*1000000 == [[1]*1000000]*1000000)"/>'
        '<node pkg="ros_tutorials_topic" type="talker" name="$(arg x)"/></launch>\n'
    )
    line = fails("roslaunch", str(path), "--print", timeout=120)
    assert line.startswith(f"error: {path}:1: $(eval [[1]*1000000]*1000000 ==")
    assert line.endswith("failed: a value longer than 1048576 characters")


def test_an_unknown_package_lists_what_ros2_pkg_list_shows_nearest_first():
    """`ros2 run`, rosrun and a launch file's $(find-pkg-share) name an unknown package in
    one line: the packages `ros2 pkg list` shows and the names `ros2 run` takes for them
    (demo_nodes_cpp, the seeds'), the nearest names first (turtlesim for turtlesm)."""
    listed = ok("ros2", "pkg", "list").split()
    line = fails("rosrun", "turtlesm", "turtlesim_node").removeprefix("error: ")
    start = "unknown package 'turtlesm'; known packages: "
    assert line.startswith(start), line
    named = line.removeprefix(start).split(", ")
    assert named[0] == "turtlesim", named[:5]
    seeds = {name for name in packages.PACKAGE_ALIASES if packages.resolve_package(name)}
    assert sorted(named) == sorted({*listed, *seeds})
    assert {"turtlesim", "xacro", "demo_nodes_cpp"} <= set(named)
    assert fails("ros2", "run", "turtlesm", "turtlesim_node") == (
        f"error: Package 'turtlesm' not found ({line})"
    )
    with pytest.raises(packages.UnknownPackage) as raised:
        packages.share_directory("turtlesm")  # $(find-pkg-share turtlesm) in a launch file
    assert str(raised.value) == line
    # `ros2 launch PKG FILE` and roslaunch give the same line.
    assert fails("ros2", "launch", "turtlesm", "x.launch.py") == f"error: {line}"
    assert fails("roslaunch", "turtlesm", "x.launch") == f"error: {line}"


@pytest.mark.parametrize(
    "package,executable,twin",
    [
        ("cpp_pubsub", "talker", "py_pubsub"),
        ("examples_rclcpp_minimal_subscriber", "subscriber_member_function",
         "examples_rclpy_minimal_subscriber"),
    ],
)  # fmt: skip
def test_a_cpp_package_of_the_pages_names_its_python_twin(package, executable, twin):
    line = fails("rosrun", package, executable)
    assert line == (
        f"error: '{package}' is a C++ package of the official pages; rclcpp, ROS 2's C++ "
        "client library, is not available without a ROS installation (it is not on PyPI): the "
        "C++ pages cannot build here; their Python twins are listed in "
        f"{Path(__file__).resolve().parent.parent / 'docs' / 'official-tutorials.md'}; this "
        f"one's is {twin}"
    ), line
    assert fails("ros2", "run", package, executable) == (
        f"error: Package '{package}' not found ({line.removeprefix('error: ')})"
    )
