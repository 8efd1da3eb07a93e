"""The one launch model (issue 34): the same tutorials in three formats give one plan, the
launch files people write load (ROS 1 <param command>, lists of lists, <test>; ROS 2
undeclared arguments, allow_substs, $(file-content), backslash escapes, composable nodes),
the Python API's module paths and arguments, and the cap on what one launch may expand to."""

from __future__ import annotations

import os
import select
from pathlib import Path

import pytest
from helpers import TIMEOUT, run

from launcher import CodeRefused, LaunchError
from launcher.loading import resolve
from launcher.plan import make_plan
from launcher.scope import Options
from ros_tutorials_common.bounded import read_params_file

TUTORIAL_PREFIX = Path(__file__).parent / "data" / "launch_tutorial"
TUTORIAL = TUTORIAL_PREFIX / "share" / "launch_tutorial" / "launch"


@pytest.fixture
def tutorial_package(monkeypatch):
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(TUTORIAL_PREFIX))
    return TUTORIAL


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def summary(path: Path, **args: str) -> list[tuple]:
    """What makes two plans the same: labels, nodes, commands (without the interpreter or the
    shell of an <executable>), remaps, parameters and when each starts."""
    launch = resolve(path, args, Options())
    out = []
    for spec in make_plan(launch):
        command = spec.command[2:] if spec.command[:2] == ["/bin/sh", "-c"] else spec.command
        words = " ".join(command[1:]) if spec.node else " ".join(command)
        words = words.replace('"', "")  # the Python files run these through a shell, quoted
        out.append((spec.label, spec.node, words, spec.remaps, spec.params, spec.when))
    return out


LAUNCH_SYSTEM = {  # Launch-system (Integrating launch files into ROS 2 packages)
    "py": "import launch\nimport launch_ros.actions\n\n\ndef generate_launch_description():\n"
    "    return launch.LaunchDescription([\n        launch_ros.actions.Node(\n"
    "            package='demo_nodes_cpp',\n            executable='talker',\n"
    "            name='talker'),\n  ])\n",
    "xml": '<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>\n</launch>\n',
    "yaml": 'launch:\n\n- node:\n    pkg: "demo_nodes_cpp"\n    exec: "talker"\n'
    '    name: "talker"\n',
}


@pytest.mark.parametrize("tutorial", ["mimic", "substitutions", "launch-system"])
def test_the_tutorials_are_one_plan_in_python_xml_and_yaml(tutorial_package, tmp_path, tutorial):
    paths = {}
    for fmt in ("py", "xml", "yaml"):
        if tutorial == "mimic":
            paths[fmt] = tutorial_package / f"turtlesim_mimic_launch.{fmt}"
        elif tutorial == "substitutions":  # the main file includes the substitutions one
            paths[fmt] = tutorial_package / f"example_main_launch.{fmt}"
        else:
            paths[fmt] = write(tmp_path, f"my_script_launch.{fmt}", LAUNCH_SYSTEM[fmt])
    plans = {fmt: summary(path) for fmt, path in paths.items()}
    if tutorial == "substitutions":  # the docs' Python file spawns at x 2, the others at x 5
        plans["py"] = [(*entry[:2], entry[2].replace("{x: 2,", "{x: 5,"), *entry[3:])
                       for entry in plans["py"]]  # fmt: skip
    assert plans["py"] == plans["xml"] == plans["yaml"]
    assert plans["py"]  # something was planned
    if tutorial == "substitutions":  # the timer's change happens: use_provided_red is True
        assert plans["py"][-1][2].endswith("turtlesim2/sim background_r 200")


def test_an_event_handlers_substitutions_are_performed_when_the_event_happens(
    tutorial_package, monkeypatch
):
    # Using-Event-Handlers where USER is unset (a container, a service): the file loads, as
    # it does with ros2 launch; only when the turtlesim exits is the variable read.
    monkeypatch.delenv("USER", raising=False)
    launch = resolve(tutorial_package / "example_event_handlers_launch.py", {}, Options())
    (closed,) = [s for s in launch.steps if s.kind == "call" and s.when.event == "exit"]
    (said,) = closed.call({"returncode": 0, "pid": 1})
    assert said.kind == "error" and "USER" in said.text
    monkeypatch.setenv("USER", "learner")
    (said,) = closed.call({"returncode": 0, "pid": 1})
    assert (said.kind, said.text) == ("log", "learner closed the turtlesim window")


# -- ROS 1 files people write ------------------------------------------------------------------


def ros1(tmp_path: Path, body: str) -> Path:
    return write(tmp_path, "robot.launch", f"<launch>\n{body}\n</launch>\n")


NODE1 = '<node pkg="ros_tutorials_topic" type="talker" name="talker"/>'


def test_param_command_runs_the_program_with_allow_code(tmp_path):
    urdf = write(tmp_path, "robot.urdf", '<robot name="r"/>\n')
    path = ros1(tmp_path, f'<param name="robot_description" command="cat {urdf}"/>\n{NODE1}')
    with pytest.raises(CodeRefused) as refused:  # a program runs: the $(eval) rule
        resolve(path, {}, Options())
    assert f"{path}:2: <param command='cat {urdf}'> runs a program" in str(refused.value)
    launch = resolve(path, {}, Options(allow_code=True))
    assert dict(launch.nodes[0].params)["robot_description"] == '<robot name="r"/>\n'


def test_param_command_that_fails_is_one_line(tmp_path):
    path = ros1(tmp_path, f'<param name="d" command="false"/>\n{NODE1}')
    with pytest.raises(LaunchError) as raised:
        resolve(path, {}, Options(allow_code=True))
    assert f"{path}:2: <param command='false'> failed: exit code 1" in str(raised.value)


def test_a_list_of_lists_goes_on_as_its_yaml_text_with_one_warning(tmp_path):
    path = ros1(
        tmp_path,
        '<node pkg="ros_tutorials_topic" type="talker" name="talker">\n'
        "  <rosparam>footprint: [[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1]]\n"
        "robot_radius: 0.2</rosparam>\n</node>",
    )
    launch = resolve(path, {}, Options())
    params = dict(launch.nodes[0].params)
    assert params == {"footprint": "[[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1]]", "robot_radius": 0.2}
    (warning,) = [w for w in launch.warnings if "list of lists" in w]
    assert warning.startswith(f"{path}:3: param 'footprint' is a list of lists")


def test_test_elements_are_ignored_with_one_note(tmp_path):
    path = ros1(
        tmp_path,
        f'{NODE1}\n<test test-name="talks" pkg="ros_tutorials_topic" type="test_talker"/>\n'
        '<test test-name="again" pkg="ros_tutorials_topic" type="test_talker" time-limit="9">\n'
        '  <param name="x" value="1"/>\n</test>',
    )
    launch = resolve(path, {}, Options())
    assert [node.name for node in launch.nodes] == ["talker"]
    (note,) = [w for w in launch.warnings if "<test>" in w]
    assert note.startswith("ignored 2 <test> (roslaunch leaves them to rostest")
    assert f"talks ({path}:3), again ({path}:4)" in note


# -- ROS 2 files people write ------------------------------------------------------------------


def test_an_include_argument_the_file_does_not_declare_is_set(tmp_path):
    write(
        tmp_path,
        "map.launch.xml",
        '<launch>\n<executable cmd="echo $(var map_path)"/>\n</launch>\n',
    )
    path = write(
        tmp_path,
        "main.launch.xml",
        '<launch>\n<include file="map.launch.xml">\n'
        '  <arg name="map_path" value="/maps/a.yaml"/>\n</include>\n</launch>\n',
    )
    launch = resolve(path, {}, Options())
    assert launch.nodes[0].cmd == ["echo", "/maps/a.yaml"]
    assert not launch.warnings  # it is read: no typo


def test_a_command_line_argument_nothing_declares_is_a_configuration(tmp_path):
    path = write(tmp_path, "t.launch.yaml", "launch:\n- executable: {cmd: echo $(var who)}\n")
    assert resolve(path, {"who": "me"}, Options()).nodes[0].cmd == ["echo", "me"]


@pytest.mark.parametrize("fmt", ["xml", "py"])
def test_a_params_file_with_allow_substs_gets_its_substitutions(tmp_path, fmt):
    params = write(tmp_path, "p.yaml", "/**:\n  ros__parameters:\n    topic: $(var topic)\n")
    text = {
        "xml": "<launch>\n<arg name='topic' default='news'/>\n"
        "<node pkg='ros_tutorials_topic' exec='talker'>\n"
        f"  <param from='{params}' allow_substs='true'/>\n</node>\n</launch>\n",
        "py": "from launch import LaunchDescription\n"
        "from launch.actions import DeclareLaunchArgument\n"
        "from launch_ros.actions import Node\n"
        "from launch_ros.parameter_descriptions import ParameterFile\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([DeclareLaunchArgument('topic', default_value='news'),\n"
        "        Node(package='ros_tutorials_topic', executable='talker',\n"
        f"             parameters=[ParameterFile('{params}', allow_substs=True)])])\n",
    }[fmt]
    launch = resolve(write(tmp_path, f"t.launch.{fmt}", text), {}, Options())
    (given,) = launch.nodes[0].params_files
    assert given != str(params)  # a file of its own; the original is left as it is
    assert read_params_file(given) == {"/**": {"ros__parameters": {"topic": "news"}}}
    assert "$(var topic)" in params.read_text()


def test_file_content_substitution(tmp_path):
    write(tmp_path, "msg.txt", "hello from a file")
    path = write(
        tmp_path,
        "t.launch.xml",
        f'<launch>\n<log message="$(file-content {tmp_path}/msg.txt)"/>\n</launch>',
    )
    assert resolve(path, {}, Options()).messages == ["hello from a file"]
    (tmp_path / "msg.txt").unlink()
    with pytest.raises(LaunchError) as raised:
        resolve(path, {}, Options())
    assert f"{path}:2: $(file-content): " in str(raised.value)


@pytest.mark.parametrize(
    ("value", "expected"),
    [
        ("$(eval '\\'$(var x)\\' != \\'\\'')", "True"),  # launch_xml's own test case
        ("\\$(var x) is $(var x)", "$(var x) is abc"),
        ("a\\\\b", "a\\b"),
        ("$(eval '\\'$(var empty)\\' != \\'\\'')", "False"),
    ],
)
def test_backslash_escapes_in_ros2_attributes(tmp_path, value, expected):
    path = write(
        tmp_path,
        "t.launch.xml",
        "<launch>\n<let name='x' value='abc'/>\n"
        f"<let name='empty' value=''/>\n<log message=\"{value}\"/>\n</launch>",
    )
    assert resolve(path, {}, Options()).messages == [expected]


def test_ros1_attributes_keep_their_backslashes(tmp_path):
    path = ros1(
        tmp_path, f'<arg name="re" default="a\\d+"/>\n<param name="re" value="$(arg re)"/>\n{NODE1}'
    )
    assert dict(resolve(path, {}, Options()).nodes[0].params)["re"] == "a\\d+"


# -- composable nodes ----------------------------------------------------------------------------

CONTAINERS = {
    "xml": """<launch>
<node_container pkg="rclcpp_components" exec="component_container" name="c" namespace="ns">
  <composable_node pkg="composition" plugin="composition::Talker" name="talker">
    <remap from="chatter" to="news"/>
    <param name="rate" value="2"/>
    <extra_arg name="use_intra_process_comms" value="true"/>
  </composable_node>
  <composable_node pkg="composition" plugin="composition::Listener" name="listener"/>
</node_container>
<load_composable_node target="/ns/c">
  <composable_node pkg="composition" plugin="composition::Server" name="server"/>
</load_composable_node>
<node pkg="ros_tutorials_topic" exec="talker"/>
</launch>
""",
    "yaml": """launch:
- node_container:
    pkg: rclcpp_components
    exec: component_container
    name: c
    namespace: ns
    composable_node:
    - pkg: composition
      plugin: composition::Talker
      name: talker
      remap: [{from: chatter, to: news}]
      param: [{name: rate, value: '2'}]
      extra_arg: [{name: use_intra_process_comms, value: 'true'}]
    - {pkg: composition, plugin: composition::Listener, name: listener}
- load_composable_node:
    target: /ns/c
    composable_node:
    - {pkg: composition, plugin: composition::Server, name: server}
- node: {pkg: ros_tutorials_topic, exec: talker}
""",
    "py": """from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, Node
from launch_ros.descriptions import ComposableNode

def generate_launch_description():
    container = ComposableNodeContainer(
        name='c', namespace='ns', package='rclcpp_components', executable='component_container',
        composable_node_descriptions=[
            ComposableNode(package='composition', plugin='composition::Talker', name='talker',
                           remappings=[('chatter', 'news')], parameters=[{'rate': 2}],
                           extra_arguments=[{'use_intra_process_comms': 'true'}]),
            ComposableNode(package='composition', plugin='composition::Listener',
                           name='listener'),
        ])
    load = LoadComposableNodes(target_container='/ns/c', composable_node_descriptions=[
        ComposableNode(package='composition', plugin='composition::Server', name='server')])
    return LaunchDescription([container, load,
                              Node(package='ros_tutorials_topic', executable='talker')])
""",
}


@pytest.mark.parametrize("fmt", ["xml", "yaml", "py"])
def test_composable_nodes_are_planned_and_not_started(tmp_path, fmt):
    path = write(tmp_path, f"t.launch.{fmt}", CONTAINERS[fmt])
    launch = resolve(path, {}, Options())
    assert [node.executable for node in launch.nodes] == ["talker"]  # the rest still runs
    container, load = launch.containers
    assert (container.name, container.package, container.executable) == (
        "/ns/c",
        "rclcpp_components",
        "component_container",
    )
    talker, listener = container.components
    # launch_ros: a component's namespace is the pushed one, not its container's
    assert (talker.namespace, talker.name, talker.plugin) == (
        "/",
        "talker",
        "composition::Talker",
    )
    assert (talker.remaps, talker.params) == ([("chatter", "news")], [("rate", 2)])
    assert talker.extra_args == [("use_intra_process_comms", "true")]
    assert listener.name == "listener" and (load.name, load.package) == ("/ns/c", None)
    assert [c.name for c in load.components] == ["server"]
    (line,) = [w for w in launch.warnings if "rclcpp_components" in w]
    assert line.startswith("component containers need rclcpp_components, which is not on PyPI")
    assert "/talker (composition::Talker)" in line and "components for /ns/c" in line


def test_print_shows_the_container_and_its_components(tmp_path):
    path = write(tmp_path, "t.launch.xml", CONTAINERS["xml"])
    result = run("ros2", "launch", str(path), "--print")
    assert result.returncode == 0, result.stderr
    assert "[container /ns/c]" in result.stdout
    assert "    component: /talker = composition composition::Talker" in result.stdout
    assert "        remap:   chatter -> news" in result.stdout
    assert "[load into /ns/c]" in result.stdout
    assert "component containers need rclcpp_components" in result.stderr


# -- the Python API ------------------------------------------------------------------------------


def test_the_module_paths_launch_files_import():
    import launch.events
    from launch.events.process import ProcessExited, ProcessStarted
    from launch.launch_context import LaunchContext
    from launch.substitutions import LaunchConfiguration
    from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

    assert launch.events.process.ProcessExited is ProcessExited
    assert isinstance(ProcessStarted(pid=1), launch.events.Event)
    context = LaunchContext()  # as ros2/launch's own tests make one
    context.launch_configurations["who"] = "me"
    subs = normalize_to_list_of_substitutions(["hi ", LaunchConfiguration("who")])
    assert [type(s).__name__ for s in subs] == ["TextSubstitution", "LaunchConfiguration"]
    assert perform_substitutions(context, subs) == "hi me"


def test_execute_process_log_cmd_and_emulate_tty(tmp_path):
    path = write(
        tmp_path,
        "t.launch.py",
        """from launch import LaunchDescription
from launch.actions import ExecuteProcess

def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=['echo', 'hi'], log_cmd=True, emulate_tty=True),
        ExecuteProcess(cmd=['echo', 'plain']),
    ])
""",
    )
    launch = resolve(path, {}, Options())
    coloured, plain = launch.nodes
    assert coloured.env.get("RCUTILS_COLORIZED_OUTPUT") == "1"
    assert "RCUTILS_COLORIZED_OUTPUT" not in plain.env
    (step,) = launch.steps
    assert (step.when.event, step.when.target) == ("start", 0)
    (logged,) = step.call({"pid": 1, "cmd": ["echo", "hi"], "cwd": None})
    assert logged.text == "process details: cmd=[echo, hi], cwd='None', custom_env?=False"


def test_log_cmd_is_said_when_the_process_starts(tmp_path):
    path = write(
        tmp_path,
        "t.launch.py",
        """from launch import LaunchDescription
from launch.actions import ExecuteProcess

def generate_launch_description():
    return LaunchDescription([ExecuteProcess(cmd=['true'], log_cmd=True)])
""",
    )
    result = run("ros2", "launch", str(path), timeout=60)
    assert result.returncode == 0, result.stderr
    assert "process details: cmd=[true], cwd='None', custom_env?=False" in (
        result.stdout + result.stderr
    )


# -- what one launch may expand to ---------------------------------------------------------------


def test_a_large_argument_used_many_times_is_refused_at_the_line_that_crossed_the_cap(tmp_path):
    big = "x" * 500_000
    logs = "".join('<log message="$(var b)"/>\n' for _ in range(100))
    path = write(
        tmp_path,
        "t.launch.xml",
        f'<launch>\n<let name="a" value="{big}"/>\n'
        f'<let name="b" value="$(var a)$(var a)"/>\n{logs}</launch>\n',
    )
    with pytest.raises(LaunchError) as raised:
        resolve(path, {}, Options())
    message = str(raised.value)
    assert "this launch's substitutions expand to more than 64 MiB in all; refusing" in message
    line = int(message.split(":")[1])
    assert 4 < line < 104  # a <log>, not the first ones: each attribute was within its cap


def test_the_refusal_is_one_line_from_the_command(tmp_path):
    big = "y" * 900_000
    logs = "".join('<log message="$(var a)"/>\n' for _ in range(80))
    path = write(
        tmp_path, "t.launch.xml", f'<launch>\n<let name="a" value="{big}"/>\n{logs}</launch>\n'
    )
    result = run("ros2", "launch", str(path), "--print")
    assert result.returncode == 1 and "Traceback" not in result.stderr
    assert result.stderr.strip().count("\n") == 0
    assert "MiB in all; refusing" in result.stderr


def test_handle_once_handles_only_the_first_event(tmp_path):
    path = write(
        tmp_path,
        "t.launch.py",
        """from launch import LaunchDescription
from launch.actions import ExecuteProcess, LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessExit

def generate_launch_description():
    flaky = ExecuteProcess(cmd=['false'], respawn=True)
    return LaunchDescription([flaky, RegisterEventHandler(OnProcessExit(
        target_action=flaky, on_exit=[LogInfo(msg='first exit')], handle_once=True))])
""",
    )
    launch = resolve(path, {}, Options())
    (step,) = launch.steps
    first, second = {"returncode": 1, "pid": 1}, {"returncode": 1, "pid": 2}
    assert [s.text for s in step.call(first)] == ["first exit"]
    assert step.call(second) == []


def test_what_this_launcher_cannot_honour_is_said_not_dropped(tmp_path):
    path = write(
        tmp_path,
        "t.launch.py",
        """from launch import LaunchDescription
from launch.actions import ExecuteProcess, TimerAction

def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=['true'], output_format='{line}'),
        TimerAction(period=1.0, actions=[], cancel_on_shutdown=False),
    ])
""",
    )
    launch = resolve(path, {}, Options())
    assert launch.nodes[0].output_format == "{line}"  # honoured: the supervisor formats lines
    assert not any("output_format" in w for w in launch.warnings)
    assert any(":7: TimerAction(cancel_on_shutdown=False)" in w for w in launch.warnings)
    bad = path.read_text().replace("'{line}'", "'{line} {nme}'")
    with pytest.raises(LaunchError, match=r":6: output_format '\{line\} \{nme\}' cannot be"):
        resolve(write(tmp_path, "bad.launch.py", bad), {}, Options())
    text = path.read_text().replace("cancel_on_shutdown=False", "cancel_on_shutdwn=False")
    with pytest.raises(LaunchError) as raised:  # a misspelt keyword is the file's own error
        resolve(write(tmp_path, "t.launch.py", text), {}, Options())
    assert "cancel_on_shutdwn" in str(raised.value)


def test_a_value_that_is_no_text_is_refused_at_the_files_line(tmp_path):
    path = write(
        tmp_path,
        "t.launch.py",
        """from launch import LaunchDescription
from launch.actions import LogInfo

def generate_launch_description():
    return LaunchDescription([LogInfo(msg=None)])
""",
    )
    with pytest.raises(LaunchError) as raised:
        resolve(path, {}, Options())
    assert str(raised.value) == f"{path}:5: expected text or substitutions, got NoneType"


def test_a_command_ends_or_is_ended_within_its_time(tmp_path, monkeypatch):
    """$(command) (as Command and <param command>): no terminal input, so `cat` ends at once;
    a command that leaves a child holding its output is ended at its time limit, child too."""
    import launch_foundation.substitutions

    monkeypatch.setattr(launch_foundation.substitutions, "COMMAND_SECONDS", 3.0)
    reads = write(tmp_path, "reads.launch.xml", '<launch><let name="x" value="[$(command cat)]"/>'
                  '<log message="got $(var x)"/></launch>')  # fmt: skip
    assert resolve(reads, {}, Options(allow_code=True)).messages == ["got []"]
    marker = tmp_path / "child.pid"
    leaves = write(
        tmp_path,
        "leaves.launch.xml",
        '<launch><let name="x" value="$(command \'sh -c &quot;sleep 600 &amp; echo $! > '
        f"{marker}; echo hi&quot;')\"/></launch>",
    )
    with pytest.raises(LaunchError, match=r":1: \$\(command sh -c .*\) failed: it ended, but a "
                       "process it left in the background keeps its output open"):  # fmt: skip
        resolve(leaves, {}, Options(allow_code=True))
    assert _ends(int(marker.read_text())), "the child the command left behind is still running"
    runs = write(tmp_path, "runs.launch.xml",
                 '<launch><let name="x" value="$(command \'sleep 600\')"/></launch>')  # fmt: skip
    with pytest.raises(
        LaunchError, match=r"\$\(command sleep 600\) failed: still running after 3 s"
    ):
        resolve(runs, {}, Options(allow_code=True))


def _ends(pid: int) -> bool:
    """Process ``pid`` ends (or has ended) within TIMEOUT: SIGKILL is delivered after kill()
    returns, so wait for it, bounded."""
    try:
        process = os.pidfd_open(pid)
    except ProcessLookupError:
        return True
    try:
        ended, _, _ = select.select([process], [], [], TIMEOUT)
    finally:
        os.close(process)
    return bool(ended)


def _setsid_grandchild(marker: Path, then: str) -> str:
    """A $(command) whose grandchild leaves the command's session (setsid) keeping its output
    open, its pid written to ``marker``; the command then runs ``then``."""
    script = marker.with_suffix(".sh")
    script.write_text(
        f"( setsid sh -c 'echo $$ > {marker}.tmp; mv {marker}.tmp {marker}; exec sleep 600' & )\n"
        f"{then}\n"
    )
    return f"$(command 'sh {script}')"


def test_a_grandchild_in_a_session_of_its_own_neither_holds_the_launch_nor_outlives_it(
    tmp_path,
):
    # ( setsid sleep & ); echo hi: the command has ended, but the grandchild holds its output
    # and is no longer in its process group. ros2 launch would wait for it; here it is refused
    # within BACKGROUND_SECONDS, and ended.
    marker = tmp_path / "grandchild.pid"
    let = f'<let name="x" value="{_setsid_grandchild(marker, "echo hi")}"/>'
    path = write(tmp_path, "t.launch.xml", f"<launch>{let}</launch>")
    with pytest.raises(LaunchError, match="keeps its output open"):
        resolve(path, {}, Options(allow_code=True))
    assert _ends(int(marker.read_text())), "the setsid grandchild is still running"


@pytest.mark.parametrize("signal_name", ["SIGINT", "SIGTERM"])
def test_ctrl_c_or_sigterm_during_a_command_ends_it_and_its_setsid_grandchild(
    tmp_path, signal_name
):
    import signal
    import subprocess
    import sys
    import time

    marker = tmp_path / "grandchild.pid"
    let = f'<let name="x" value="{_setsid_grandchild(marker, "sleep 600")}"/>'
    path = write(tmp_path, "t.launch.xml", f"<launch>{let}</launch>")
    launcher = subprocess.Popen(
        [sys.executable, "-m", "launcher", str(path), "--allow-code", "--print"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
    )  # fmt: skip
    try:
        deadline = time.monotonic() + TIMEOUT
        while not marker.exists() and launcher.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)  # a wait on a condition, bounded
        assert marker.exists(), launcher.stderr.read() if launcher.poll() is not None else ""
        grandchild = int(marker.read_text())
        launcher.send_signal(getattr(signal, signal_name))
        code = launcher.wait(TIMEOUT)
    finally:
        if launcher.poll() is None:
            os.killpg(launcher.pid, signal.SIGKILL)
            launcher.wait()
    assert code == (130 if signal_name == "SIGINT" else -signal.SIGTERM), launcher.stderr.read()
    assert "Traceback" not in launcher.stderr.read()
    assert _ends(grandchild), "the command's setsid grandchild outlived the launcher"


def test_the_issues_one_megabyte_argument_in_3000_params_is_refused(tmp_path):
    # A 125 KB file: a 1 MB argument, made by repetition, used by 3000 <param>s.
    params = "".join(f'<param name="p{i}" value="$(var b)"/>\n' for i in range(3000))
    path = write(
        tmp_path,
        "t.launch.xml",
        f'<launch>\n<arg name="a" default="{"x" * 1000}"/>\n'
        f'<arg name="b" default="{"$(var a)" * 1000}"/>\n'
        f'<node pkg="ros_tutorials_topic" exec="talker">\n{params}</node>\n</launch>\n',
    )
    with pytest.raises(LaunchError) as raised:
        resolve(path, {}, Options())
    where, _, message = str(raised.value).partition(": ")
    assert message == "this launch's substitutions expand to more than 64 MiB in all; refusing"
    line = int(where.rsplit(":", 1)[1])
    assert 5 < line < 3005
    assert path.read_text().splitlines()[line - 1].startswith("<param name=")


@pytest.mark.parametrize("fmt", ["xml", "py"])
def test_respawn_max_retries_means_the_same_in_every_format(tmp_path, fmt):
    # Not given: this launcher's default of 10 quick failures; -1, as in ros2 launch: for ever.
    text = {
        "xml": "<launch>\n<executable cmd='false' respawn='true'/>\n"
        "<executable cmd='false' respawn='true' respawn_max_retries='-1'/>\n</launch>\n",
        "py": "from launch import LaunchDescription\nfrom launch.actions import ExecuteProcess\n"
        "def generate_launch_description():\n    return LaunchDescription([\n"
        "        ExecuteProcess(cmd=['false'], respawn=True),\n"
        "        ExecuteProcess(cmd=['false'], respawn=True, respawn_max_retries=-1)])\n",
    }[fmt]
    default, forever = resolve(write(tmp_path, f"t.launch.{fmt}", text), {}, Options()).nodes
    assert (default.respawn_max_retries, forever.respawn_max_retries) == (10, -1)


def test_param_substitution_reads_what_set_parameter_gave_in_xml_yaml_and_python(tmp_path):
    # launch_ros's $(param NAME [DEFAULT]) / Parameter: the value a SetParameter gave before
    # it in its scope (as Python's str of the typed value), the default, else an error.
    xml = write(tmp_path, "p.launch.xml", """<launch>
<set_parameter name="use_sim_time" value="true"/>
<set_parameter name="rate" value="10"/>
<log message="$(param use_sim_time) $(param rate) $(param missing fallback)"/>
</launch>
""")  # fmt: skip
    yaml = write(tmp_path, "p.launch.yaml", """launch:
- set_parameter: {name: use_sim_time, value: "true"}
- set_parameter: {name: rate, value: "10"}
- log: {message: "$(param use_sim_time) $(param rate) $(param missing fallback)"}
""")  # fmt: skip
    python = write(tmp_path, "p.launch.py", """from launch import LaunchDescription
from launch.actions import LogInfo
from launch_ros.actions import SetParameter
from launch_ros.substitutions import Parameter

def generate_launch_description():
    return LaunchDescription([
        SetParameter(name="use_sim_time", value=True),
        SetParameter(name="rate", value=10),
        LogInfo(msg=[Parameter("use_sim_time"), " ", Parameter("rate"), " ",
                     Parameter("missing", default="fallback")]),
    ])
""")  # fmt: skip
    for path in (xml, yaml, python):
        assert resolve(path, {}, Options()).messages == ["True 10 fallback"], path.name
    unknown = write(tmp_path, "u.launch.xml", '<launch>\n<log message="$(param nope)"/>\n</launch>')
    with pytest.raises(LaunchError, match=r"u.launch.xml:2: parameter 'nope' not found"):
        resolve(unknown, {}, Options())


def test_a_params_file_rcl_will_refuse_is_passed_as_its_path_with_a_warning(tmp_path):
    # ros2 launch passes a node's parameters file on as its path, unread: a list of mixed
    # types plans (rcl refuses it when the node reads it: said once as a warning), while a
    # file that is no parameters file at all is refused at the launch file's line.
    params = tmp_path / "params.yaml"
    params.write_text("talker:\n  ros__parameters:\n    mixed: [1, 'two', 3.0]\n")
    python = write(tmp_path, "p.launch.py", f"""from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        Node(package="ros_tutorials_topic", executable="talker", parameters=[{str(params)!r}]),
    ])
""")  # fmt: skip
    xml = write(tmp_path, "p.launch.xml", f"""<launch>
<node pkg="ros_tutorials_topic" exec="talker"><param from="{params}"/></node>
</launch>
""")  # fmt: skip
    for path in (python, xml):
        launch = resolve(path, {}, Options())
        assert launch.nodes[0].params_files == [str(params)]
        assert any(
            "'mixed' mixes types in one list; a ROS list holds one type; passed to the node"
            in warning
            for warning in launch.warnings
        ), launch.warnings
        command = make_plan(launch)[0].command
        assert command[command.index("--params-file") + 1] == str(params)
    params.write_text("talker: [1, 2]\n")
    with pytest.raises(LaunchError, match=r"p.launch.xml:2: .*has no 'ros__parameters:' mapping"):
        resolve(xml, {}, Options())


def test_planning_calls_no_function_of_an_on_shutdown_handler(tmp_path):
    # An OnShutdown handler's OpaqueFunction is the launch file's clean-up: ros2 launch calls
    # it when the launch shuts down, so planning (--print) must not.
    marker = tmp_path / "cleaned"
    path = write(tmp_path, "t.launch.py", f"""from pathlib import Path
from launch import LaunchDescription
from launch.actions import OpaqueFunction, RegisterEventHandler
from launch.event_handlers import OnShutdown
from launch_ros.actions import Node

def cleanup(context):
    Path({str(marker)!r}).write_text("cleaned")

def generate_launch_description():
    return LaunchDescription([
        Node(package="ros_tutorials_topic", executable="talker"),
        RegisterEventHandler(OnShutdown(on_shutdown=[OpaqueFunction(function=cleanup)])),
    ])
""")  # fmt: skip
    done = run("ros2", "launch", str(path), "--print")
    assert done.returncode == 0, done.stderr
    assert "when the launch shuts down" in done.stdout
    assert not marker.exists(), "planning ran the OnShutdown handler's function"


def test_a_lifecycle_node_plans_as_its_node_and_needs_a_name_and_namespace(tmp_path):
    path = write(tmp_path, "t.launch.py", """from launch import LaunchDescription
from launch_ros.actions import LifecycleNode

def generate_launch_description():
    return LaunchDescription([
        LifecycleNode(package="ros_tutorials_topic", executable="talker", name="lc_talker",
                      namespace="demo", output="screen", parameters=[{"rate": 2}]),
    ])
""")  # fmt: skip
    (node,) = resolve(path, {}, Options()).nodes
    assert (node.name, node.namespace, node.params) == ("lc_talker", "/demo", [("rate", 2)])
    unnamed = write(tmp_path, "u.launch.py", """from launch import LaunchDescription
from launch_ros.actions import LifecycleNode

def generate_launch_description():
    return LaunchDescription([
        LifecycleNode(package="ros_tutorials_topic", executable="talker", name="lc_talker"),
    ])
""")  # fmt: skip
    with pytest.raises(LaunchError, match=r"u.launch.py:6: .*missing 1 required keyword-only "
                       r"argument: 'namespace'"):  # fmt: skip
        resolve(unnamed, {}, Options())


def test_a_lifecycle_transition_asked_by_the_launch_file_is_refused_in_one_line(tmp_path):
    # The launcher hosts no ROS node to call change_state: ChangeState builds, and its
    # EmitEvent is refused at the launch file's line (not a wrong plan, not a traceback).
    path = write(tmp_path, "t.launch.py", """from launch import LaunchDescription
from launch.actions import EmitEvent
from launch_ros.actions import LifecycleNode
from launch_ros.events.lifecycle import ChangeState

def generate_launch_description():
    node = LifecycleNode(package="ros_tutorials_topic", executable="talker", name="lc",
                         namespace="")
    return LaunchDescription([node, EmitEvent(event=ChangeState(
        lifecycle_node_matcher=lambda action: action is node, transition_id=1))])
""")  # fmt: skip
    with pytest.raises(LaunchError) as raised:
        resolve(path, {}, Options())
    assert str(raised.value) == (
        f"{path}:9: EmitEvent(ChangeState) is not supported here; only "
        "EmitEvent(event=Shutdown(...))"
    )


def test_launch_service_runs_a_description_through_the_launchers_entry_point(tmp_path):
    # launch finds the tool that plans and supervises by the launch.runner entry point
    # (launcher.service.run), not by importing it: a script's LaunchService still runs.
    script = tmp_path / "service.py"
    script.write_text("""import sys
from launch import LaunchDescription, LaunchService
from launch.actions import ExecuteProcess

ls = LaunchService()
ls.include_launch_description(LaunchDescription([
    ExecuteProcess(cmd=[sys.executable, "-c", "print('hello from the plan')"], output="screen"),
]))
sys.exit(ls.run())
""")
    import subprocess
    import sys

    done = subprocess.run(
        [sys.executable, str(script)], capture_output=True, text=True, timeout=TIMEOUT
    )
    assert done.returncode == 0, done.stderr
    assert "hello from the plan" in done.stdout + done.stderr
