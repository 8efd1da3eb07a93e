"""The Python launch API as public launch files use it, with ros2/launch's behaviour: paths
joined with ``/``, Command's list concatenated, FileContent, PythonExpression,
FindExecutable, LaunchConfigurationEquals, AnyLaunchDescriptionSource, OpaqueFunction
returning actions, matches_action; and LaunchService running a description from a script."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from helpers import TIMEOUT

from launcher.loading import resolve
from launcher.scope import Options

HEADER = (
    "import os\n"
    "from pathlib import Path\n"
    "from launch import LaunchDescription\n"
    "from launch.actions import (DeclareLaunchArgument, IncludeLaunchDescription, LogInfo,\n"
    "                            OpaqueFunction)\n"
    "from launch.conditions import IfCondition, LaunchConfigurationEquals\n"
    "from launch.launch_description_sources import AnyLaunchDescriptionSource\n"
    "from launch.substitutions import (Command, FileContent, FindExecutable,\n"
    "    LaunchConfiguration, PathJoinSubstitution, PathSubstitution, PythonExpression,\n"
    "    ThisLaunchFileDir, EqualsSubstitution)\n"
)


def messages(tmp_path: Path, body: str, allow_code: bool = False, **args: str) -> list[str]:
    path = tmp_path / "t_launch.py"
    path.write_text(HEADER + body)
    return resolve(path, args, Options(allow_code=allow_code)).messages


def test_path_substitution_joins_with_slash(tmp_path):
    body = (
        "def generate_launch_description():\n"
        "    urdf = PathSubstitution(ThisLaunchFileDir()) / 'urdf' / LaunchConfiguration('f')\n"
        "    also = PathJoinSubstitution([ThisLaunchFileDir(), 'config', 'a.yaml'])\n"
        "    return LaunchDescription([DeclareLaunchArgument('f', default_value='r.urdf'),\n"
        "        LogInfo(msg=urdf), LogInfo(msg=also),\n"
        "        LogInfo(msg=PathSubstitution(Path('/x')))])\n"
    )
    assert messages(tmp_path, body) == [
        f"{tmp_path}/urdf/r.urdf", f"{tmp_path}/config/a.yaml", "/x",
    ]  # fmt: skip


def test_command_concatenates_its_list_items_without_spaces(tmp_path):
    # ros2_control demos: Command([FindExecutable(name='xacro'), ' ', path, ' prefix:=', ''])
    body = (
        "def generate_launch_description():\n"
        "    return LaunchDescription([LogInfo(msg=Command([\n"
        "        FindExecutable(name='echo'), ' ', 'a', 'b', ' prefix:=', '\"\"']))])\n"
    )
    assert messages(tmp_path, body) == ["ab prefix:=\n"]


def test_file_content_and_python_expression(tmp_path):
    (tmp_path / "robot.txt").write_text("<robot/>")
    body = (
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('n', default_value='3'),\n"
        "        LogInfo(msg=FileContent(PathSubstitution(ThisLaunchFileDir()) / 'robot.txt')),\n"
        "        LogInfo(msg=PythonExpression([LaunchConfiguration('n'), ' * 2'])),\n"
        "        LogInfo(msg=PythonExpression(['sqrt(', LaunchConfiguration('n'), ' ** 2)'])),\n"
        "    ])\n"
    )
    assert messages(tmp_path, body) == ["<robot/>", "6", "3.0"]


def test_conditions_on_launch_configurations(tmp_path):
    body = (
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('mode', default_value='sim'),\n"
        "        LogInfo(msg='equals', condition=LaunchConfigurationEquals('mode', 'sim')),\n"
        "        LogInfo(msg='if', condition=IfCondition(\n"
        "            EqualsSubstitution(LaunchConfiguration('mode'), 'real'))),\n"
        "    ])\n"
    )
    with pytest.warns(UserWarning, match="LaunchConfigurationEquals is deprecated"):
        assert messages(tmp_path, body) == ["equals"]
        assert messages(tmp_path, body, mode="real") == ["if"]


def test_opaque_function_returns_actions_and_any_source_includes_xml(tmp_path):
    (tmp_path / "inner.launch.xml").write_text(
        '<launch><arg name="who"/><log message="inner $(var who)"/></launch>'
    )
    body = (
        "def setup(context, greeting):\n"
        "    n = int(LaunchConfiguration('n').perform(context))\n"
        "    return [LogInfo(msg=f'{greeting} {i}') for i in range(n)]\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('n', default_value='2'),\n"
        "        OpaqueFunction(function=setup, args=['hello']),\n"
        "        IncludeLaunchDescription(AnyLaunchDescriptionSource(\n"
        "            PathJoinSubstitution([ThisLaunchFileDir(), 'inner.launch.xml'])),\n"
        "            launch_arguments={'who': 'me'}.items()),\n"
        "    ])\n"
    )
    assert messages(tmp_path, body) == ["hello 0", "hello 1", "inner me"]


def test_matches_action_picks_its_action():
    from launch.actions import LogInfo
    from launch.events import matches_action

    first, second = LogInfo(msg="a"), LogInfo(msg="b")
    matcher = matches_action(first)
    assert matcher(first) and not matcher(second)


def test_launch_service_runs_a_description_from_a_script(tmp_path):
    script = tmp_path / "run.py"
    script.write_text(
        "import sys\n"
        "from launch import LaunchDescription, LaunchService\n"
        "from launch.actions import ExecuteProcess, LogInfo\n"
        "ls = LaunchService()\n"
        "ls.include_launch_description(LaunchDescription([LogInfo(msg='from the script'),\n"
        "    ExecuteProcess(cmd=['echo', 'from echo'], output='screen')]))\n"
        "sys.exit(ls.run())\n"
    )
    done = subprocess.run(
        [sys.executable, str(script)], capture_output=True, text=True, timeout=TIMEOUT
    )
    assert done.returncode == 0, done.stderr
    assert "[INFO] [launch.user]: from the script" in done.stdout
    assert "from echo" in done.stdout
    assert "process has finished cleanly" in done.stdout


def test_launch_service_says_a_bad_description_in_one_line(tmp_path, capsys):
    from launch import LaunchDescription, LaunchService
    from launch.actions import LogInfo
    from launch.substitutions import LaunchConfiguration

    service = LaunchService()
    service.include_launch_description(LaunchDescription([LogInfo(msg=LaunchConfiguration("x"))]))
    assert service.run() == 1
    error = capsys.readouterr().err
    assert error.startswith("error: ") and "launch configuration 'x' is not set" in error
    with pytest.raises(Exception, match="takes a LaunchDescription"):
        service.include_launch_description("not a description")


def test_output_as_a_dict_of_streams_and_the_arguments_import_place(tmp_path):
    # ros2_control's test nodes: output={"stdout": "screen", "stderr": "screen"}
    from launcher.plan import make_plan

    path = tmp_path / "t_launch.py"
    path.write_text(
        "from launch import LaunchDescription\n"
        "from launch.launch_description import DeclareLaunchArgument\n"
        "from launch.actions import ExecuteProcess\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([DeclareLaunchArgument('x', default_value='1'),\n"
        "        ExecuteProcess(cmd=['true'], name='a', output={'stdout': 'screen',"
        " 'stderr': 'screen'}),\n"
        "        ExecuteProcess(cmd=['true'], name='b', output={'stdout': 'log',"
        " 'stderr': 'screen'})])\n"
    )
    specs = make_plan(resolve(path, {}, Options()))
    assert [(spec.label, spec.output) for spec in specs] == [("a", "screen"), ("b", "both")]


def test_executable_description_performs_its_parts(monkeypatch):
    from launch import LaunchContext
    from launch.descriptions import Executable
    from launch.substitutions import EnvironmentVariable, LaunchConfiguration

    monkeypatch.setenv("LAUNCH_API_DIR", "/tmp")
    context = LaunchContext()
    context.launch_configurations["who"] = "me"
    exe = Executable(
        cmd=["echo", LaunchConfiguration("who")], prefix="nice -n 5",
        cwd=EnvironmentVariable("LAUNCH_API_DIR"), additional_env={"X": "1"},
    )  # fmt: skip
    exe.prepare(context, None)
    assert exe.final_cmd == ["nice", "-n", "5", "echo", "me"]
    assert (exe.final_name, exe.final_cwd, exe.final_env["X"]) == ("echo", "/tmp", "1")
