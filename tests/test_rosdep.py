"""`rosdep` answered from this environment (ros2cmd/rosdep.py): the package pages'
`rosdep install -i --from-path src --rosdistro jazzy -y`, and the Rosdep page's `rosdep init`,
`rosdep update`, in a workspace of packages `ros2 pkg create` makes."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROSDEP = Path(sys.prefix) / "bin" / "rosdep"
ROS2 = Path(sys.prefix) / "bin" / "ros2"
PAGES_LINE = ["install", "-i", "--from-path", "src", "--rosdistro", "jazzy", "-y"]
TIMEOUT = 60.0


def run(workspace: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(ROSDEP), *args], cwd=workspace, capture_output=True, text=True, timeout=TIMEOUT
    )


def create(workspace: Path, *args: str) -> None:
    (workspace / "src").mkdir(parents=True, exist_ok=True)
    subprocess.run(
        [str(ROS2), "pkg", "create", *args],
        cwd=workspace / "src",
        check=True,
        capture_output=True,
        timeout=TIMEOUT,
    )


def add_depend(workspace: Path, package: str, line: str) -> None:
    manifest = workspace / "src" / package / "package.xml"
    text = manifest.read_text()
    manifest.write_text(text.replace("  <test_depend>", f"  {line}\n  <test_depend>", 1))


def test_all_dependencies_here_is_rosdeps_success_line(tmp_path):
    """A Python package and an interface package of the pages: everything they name is in
    this environment (rclpy, std_msgs, the linters, pytest; the interface package's lint
    test dependencies only with a note, as BUILD_TESTING is off here)."""
    create(tmp_path, "--build-type", "ament_python", "py_pubsub", "--dependencies", "rclpy")
    add_depend(tmp_path, "py_pubsub", "<exec_depend>std_msgs</exec_depend>")
    create(tmp_path, "--build-type", "ament_cmake", "tutorial_interfaces")
    add_depend(tmp_path, "tutorial_interfaces", "<depend>geometry_msgs</depend>")
    # -i: a key that is a package of the workspace is left to colcon.
    add_depend(tmp_path, "py_pubsub", "<depend>tutorial_interfaces</depend>")
    result = run(tmp_path, *PAGES_LINE)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "#All required rosdeps installed successfully\n"
    assert result.stderr == (
        "note: tutorial_interfaces: ament_lint_auto, ament_lint_common (test dependencies) "
        "are not on PyPI: `colcon build` here leaves BUILD_TESTING off and does not need them\n"
    )
    keys = run(tmp_path, "keys", "-i", "--from-paths", "src")
    assert keys.returncode == 0 and "tutorial_interfaces" not in keys.stdout.split()
    assert {"rclpy", "std_msgs", "geometry_msgs", "python3-pytest"} <= set(keys.stdout.split())
    checked = run(tmp_path, "check", "-i", "--from-paths", "src")
    assert checked.stdout == "All system dependencies have been satisfied\n"
    # Without -i, the workspace's own package is a key not installed here.
    result = run(tmp_path, "install", "--from-paths", "src", "-y")
    assert result.returncode == 1
    assert "py_pubsub: tutorial_interfaces: a package of your workspace, not installed: add -i" in (
        result.stderr
    )


def test_missing_keys_are_named_with_how_to_get_them(tmp_path):
    """rosdep's error, then one line per missing key: rclcpp needs a ROS installation, a
    Python key its PyPI name, a ROS package PyPI may have; status 1."""
    create(tmp_path, "--build-type", "ament_cmake", "cpp_pubsub", "--dependencies", "rclcpp")
    create(tmp_path, "--build-type", "ament_python", "my_package")
    add_depend(tmp_path, "my_package", "<exec_depend>python3-no-such-thing</exec_depend>")
    add_depend(tmp_path, "my_package", "<exec_depend>nav2_msgs</exec_depend>")
    result = run(tmp_path, *PAGES_LINE)
    assert result.returncode == 1 and result.stdout == ""
    lines = [line for line in result.stderr.splitlines() if not line.startswith("note: ")]
    assert lines[:2] == [
        "ERROR: the following packages/stacks could not have their rosdep keys resolved",
        "to system dependencies:",
    ]
    assert lines[2].startswith(
        "cpp_pubsub: rclcpp: rclcpp, ROS 2's C++ client library, is not available without a "
        "ROS installation (it is not on PyPI)"
    )
    assert lines[3:] == [
        "my_package: python3-no-such-thing: pip install no-such-thing",
        "my_package: nav2_msgs: no package 'nav2_msgs' in the ament index: if PyPI has it, "
        "pip install ros-jazzy-nav2-msgs; otherwise it needs a ROS installation",
    ]
    # --skip-keys leaves them out, as rosdep does.
    skipped = run(tmp_path, *PAGES_LINE, "--skip-keys", "rclcpp python3-no-such-thing nav2_msgs")
    assert skipped.returncode == 0, skipped.stderr


def test_init_update_and_bad_input_are_one_line(tmp_path):
    for command in ("init", "update"):
        result = run(tmp_path, command)
        assert result.returncode == 0 and result.stderr == ""
        assert result.stdout.startswith(f"rosdep {command}: nothing to ")
        assert result.stdout.count("\n") == 1
    for args, status, start in (
        (["install", "--from-paths", "nowhere"], 1, "error: given path 'nowhere' does not exist"),
        ([], 1, "error: Please enter a command"),
        (["install", "no_such_package"], 1, "error: no package 'no_such_package'"),
        (["resolve", "rclcpp"], 1, "error: rosdep resolve is not available here"),
        (["install", "--rosdistro", "humble", "--from-paths", "."], 1, "error: --rosdistro"),
        (["install", "--no-such-option"], 2, "rosdep: error: unrecognized arguments"),
    ):
        result = run(tmp_path, *args)
        assert result.returncode == status, (args, result.stderr)
        assert result.stderr.startswith(start) and result.stderr.count("\n") == 1, result.stderr
        assert result.stdout == ""


MANIFEST = """\
<?xml version="1.0"?>
<package format="3">
  <name>conditional</name>
  <version>0.0.0</version>
  <description>ROS 1 and ROS 2 dependencies by condition</description>
  <maintainer email="learner@example.com">learner</maintainer>
  <license>Apache-2.0</license>
  <depend condition="$ROS_VERSION == 1">rospy</depend>
  <depend condition="$ROS_VERSION == 2">rclpy</depend>
</package>
"""


def test_conditions_are_evaluated_and_a_broken_package_xml_is_one_line(tmp_path):
    manifest = tmp_path / "src" / "conditional" / "package.xml"
    manifest.parent.mkdir(parents=True)
    manifest.write_text(MANIFEST)
    keys = run(tmp_path, "keys", "--from-paths", "src")
    assert keys.returncode == 0 and keys.stdout == "rclpy\n"
    assert run(tmp_path, *PAGES_LINE).returncode == 0
    manifest.write_text(MANIFEST[:120])
    result = run(tmp_path, *PAGES_LINE)
    assert result.returncode == 1 and result.stdout == ""
    assert result.stderr.startswith("error: Error(s) in package 'src/conditional/package.xml'")
    assert result.stderr.count("\n") == 1
    # A condition catkin_pkg cannot read: one line naming the package, not a traceback.
    manifest.write_text(MANIFEST.replace('condition="', 'condition="$ROS_VERSION == ', 1))
    result = run(tmp_path, *PAGES_LINE)
    assert result.returncode == 1 and "Traceback" not in result.stderr, result.stderr
    assert result.stderr.startswith("error: package conditional: ")
    assert result.stderr.count("\n") == 1


def test_a_key_that_is_not_a_name_is_refused_and_never_part_of_a_line_to_paste(tmp_path):
    """A package.xml's key with shell in it is not looked up: it is shown quoted as a key that
    cannot be resolved; nothing printed would run it when pasted."""
    create(tmp_path, "--build-type", "ament_python", "my_package")
    add_depend(tmp_path, "my_package", "<depend>python3-numpy; touch PWNED4</depend>")
    add_depend(tmp_path, "my_package", "<depend>$(touch PWNED5)</depend>")
    add_depend(tmp_path, "my_package", "<depend>it's $(touch PWNED6)</depend>")
    result = run(tmp_path, *PAGES_LINE)
    assert result.returncode == 1 and result.stdout == ""
    lines = result.stderr.splitlines()
    assert "my_package: 'python3-numpy; touch PWNED4': not a rosdep key" in result.stderr, lines
    assert "my_package: '$(touch PWNED5)': not a rosdep key" in result.stderr, lines
    assert "pip install" not in result.stderr and "ros-jazzy-$(" not in result.stderr
    keys = run(tmp_path, "keys", "-i", "--from-paths", "src")
    assert "'python3-numpy; touch PWNED4'" in keys.stdout.splitlines()
    # Pasting every line printed runs nothing of the package.xml's.
    for line in (result.stderr + keys.stdout).splitlines():
        for word in line.split(": "):
            subprocess.run(
                ["bash", "-c", f": {word}"], cwd=tmp_path, capture_output=True, timeout=10
            )
    for name in ("PWNED4", "PWNED5", "PWNED6"):
        assert not (tmp_path / name).exists(), name


def test_system_keys_are_answered_with_the_debian_package(tmp_path):
    """doxygen, eigen are rosdep rules for system packages: apt's package, not a ROS wheel."""
    create(tmp_path, "--build-type", "ament_python", "my_package")
    add_depend(tmp_path, "my_package", "<doc_depend>doxygen</doc_depend>")
    add_depend(tmp_path, "my_package", "<depend>eigen</depend>")
    add_depend(tmp_path, "my_package", "<depend>libfoo-dev</depend>")
    result = run(tmp_path, *PAGES_LINE, "-t", "doc", "-t", "build")
    assert result.returncode == 1
    lines = result.stderr.splitlines()
    assert "my_package: doxygen: a system package, not a ROS one: sudo apt install doxygen" in lines
    assert (
        "my_package: eigen: a system package, not a ROS one: sudo apt install libeigen3-dev"
        in lines
    )
    assert "ros-jazzy-doxygen" not in result.stderr and "ros-jazzy-eigen" not in result.stderr
    assert any(line.startswith("my_package: libfoo-dev: a system package") for line in lines)


def test_a_cpp_package_in_the_workspace_leaves_the_python_ones_ready(tmp_path):
    """A learner who did the C++ pages first: rclcpp is reported as a key that cannot be
    resolved, and the line after the error says which packages are ready to build; -r, as
    rosdep's, goes on (status 0)."""
    create(tmp_path, "--build-type", "ament_cmake", "cpp_pubsub", "--dependencies", "rclcpp")
    create(tmp_path, "--build-type", "ament_python", "py_pubsub", "--dependencies", "rclpy")
    create(tmp_path, "--build-type", "ament_python", "uses_cpp", "--dependencies", "cpp_pubsub")
    result = run(tmp_path, *PAGES_LINE)
    assert result.returncode == 1 and result.stdout == ""
    lines = [line for line in result.stderr.splitlines() if not line.startswith("note: ")]
    assert lines[0].startswith("ERROR: the following packages/stacks could not have")
    assert lines[2].startswith("cpp_pubsub: rclcpp: rclcpp, ROS 2's C++ client library")
    assert lines[3:] == [
        "ready: every dependency of py_pubsub is here (colcon build --packages-select py_pubsub)"
    ]
    robust = run(tmp_path, *PAGES_LINE, "-r")
    assert robust.returncode == 0, robust.stderr
    assert robust.stdout == (
        "Continuing to install resolvable dependencies...\n"
        "#All required rosdeps installed successfully\n"
    )


def test_the_rosdep_pages_pip_install_rosdep_leaves_this_rosdep_in_place():
    """The Rosdep page's `pip install rosdep`, typed in the activated environment: rosdep is
    installed already (this environment's distribution of that name), so PyPI's, which would
    replace the `rosdep` command, is not fetched."""
    result = subprocess.run(
        [sys.executable, "-m", "pip", "install", "--dry-run", "--no-index", "rosdep"],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )
    assert result.returncode == 0, result.stderr
    assert "Requirement already satisfied: rosdep" in result.stdout, result.stdout
    assert "Would install" not in result.stdout
    shown = subprocess.run(
        [sys.executable, "-m", "pip", "show", "rosdep"], capture_output=True, text=True,
        timeout=TIMEOUT,
    )  # fmt: skip
    assert "Summary: This environment's rosdep" in shown.stdout, shown.stdout
    assert run(Path.cwd(), "init").stdout.startswith("rosdep init: nothing to set up here")
