"""A learner's own package that has a seed's name (`my_package`, issue 36), built with the real
colcon and sourced: its own executables and launch files are the ones `ros2 run`, `rosrun`,
`roslaunch`, `ros2 launch` and `ros2 pkg` find, never the seed's aliases for that name.

The package is what Creating-Your-First-ROS2-Package makes (`ros2 pkg create --build-type
ament_python my_package`), with the executables `talker` and `listener` (seed 004's names,
which this project's aliases send to the workshop lessons) and `heard.py` (a script named with
its suffix, as ROS 1 launch files name them: type="heard.py"); its launch files are installed
as Using-Parameters-In-A-Class-Python installs them, into share/my_package/ itself.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from test_workspace import add_entry_points, bash, colcon_build, create, new_workspace, ok

NODE = """def main():
    print("the learner's {name}")
"""
DATA_FILES = """        (os.path.join('share', package_name),
            glob('launch/*_launch.xml') + ['launch/both.launch.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*.launch*')),
"""
ROS1_LAUNCH = '<launch><node pkg="my_package" type="heard.py" name="heard"/></launch>\n'
ROS2_LAUNCH = '<launch><node pkg="my_package" exec="talker" name="talker"/></launch>\n'


@pytest.fixture(scope="module")
def workspace(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The built workspace (one colcon build for the module's tests)."""
    workspace = new_workspace(tmp_path_factory.mktemp("learner"))
    create(workspace, "--build-type ament_python --license Apache-2.0 my_package")
    package = workspace / "src" / "my_package"
    for name in ("talker", "listener", "heard"):
        (package / "my_package" / f"{name}.py").write_text(NODE.format(name=name))
    add_entry_points(
        package / "setup.py",
        "talker = my_package.talker:main",
        "listener = my_package.listener:main",
        "heard.py = my_package.heard:main",
    )
    setup = (package / "setup.py").read_text()
    setup = "import os\nfrom glob import glob\n" + setup.replace(
        "        ('share/' + package_name, ['package.xml']),\n",
        "        ('share/' + package_name, ['package.xml']),\n" + DATA_FILES,
    )
    (package / "setup.py").write_text(setup)
    (package / "launch").mkdir()
    (package / "launch" / "heard.launch").write_text(ROS1_LAUNCH)
    (package / "launch" / "talk_launch.xml").write_text(ROS2_LAUNCH)
    (package / "launch" / "both.launch.xml").write_text(ROS2_LAUNCH)
    colcon_build(workspace)
    return workspace


def sourced_in(workspace: Path, script: str) -> str:
    return f"source {workspace}/install/setup.bash\n{script}"


def test_ros2_pkg_lists_the_learners_executables_only(workspace):
    listed = ok(sourced_in(workspace, "ros2 pkg executables my_package"), workspace)
    assert listed == "my_package heard.py\nmy_package listener\nmy_package talker\n"


@pytest.mark.parametrize("where", ["workspace", "elsewhere"])
def test_ros2_run_and_rosrun_run_the_learners_own_talker_and_listener(workspace, where):
    cwd = workspace if where == "workspace" else workspace.parent
    for command, name in (
        ("ros2 run my_package talker", "talker"),
        ("rosrun my_package listener", "listener"),
        ("ros2 run my_package heard.py", "heard"),
    ):
        assert ok(sourced_in(workspace, command), cwd) == f"the learner's {name}\n"


def test_launch_files_run_the_learners_executables(workspace):
    lib = workspace / "install" / "my_package" / "lib" / "my_package"
    # ROS 1's type="heard.py": the installed file of that name, not "heard" with .py stripped.
    printed = ok(sourced_in(workspace, "roslaunch my_package heard.launch --print"), workspace)
    assert f"command: {lib / 'heard.py'} --ros-args" in printed
    # Installed into share/my_package/ itself, as the Python parameters page does.
    printed = ok(sourced_in(workspace, "ros2 launch my_package talk_launch.xml --print"), workspace)
    assert f"command: {lib / 'talker'} --ros-args" in printed


def test_a_launch_file_found_twice_in_the_share_directory_is_an_error_naming_both(workspace):
    share = workspace / "install" / "my_package" / "share" / "my_package"
    result = bash(sourced_in(workspace, "ros2 launch my_package both.launch.xml"), workspace)
    assert result.returncode == 1 and result.stdout == ""
    both = f"['{share / 'both.launch.xml'}', '{share / 'launch' / 'both.launch.xml'}']"
    assert result.stderr == (
        "error: file 'both.launch.xml' was found more than once in the share directory of "
        f"package 'my_package': [{both[1:-1]}]\n"
    )
