"""ros2 launch's three formats without processes: Python, YAML and XML launch files parsed and
resolved into the launcher's plan (the same plan for the same file in each format), timers,
event handlers, includes across formats, and the errors a learner meets."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from helpers import ok, run

from launch_foundation.declarations import When
from launcher import LaunchError
from launcher.loading import describe_args, resolve
from launcher.plan import make_plan
from launcher.python_files import LaunchFileRaised
from launcher.scope import Options

TUTORIAL_PREFIX = Path(__file__).parent / "data" / "launch_tutorial"
TUTORIAL = TUTORIAL_PREFIX / "share" / "launch_tutorial" / "launch"


@pytest.fixture
def tutorial_package(monkeypatch):
    """The tutorials' package `launch_tutorial` in the ament index, as a sourced workspace."""
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(TUTORIAL_PREFIX))
    return TUTORIAL


def resolved(path: Path, **args: str):
    return resolve(path, args, Options())


def planned(path: Path, **args: str):
    launch = resolved(path, **args)
    return launch, make_plan(launch)


def summary(specs) -> list[tuple]:
    """What makes two plans the same: labels, commands (without the interpreter), remaps."""
    return [(s.label, s.node, s.command[1:], s.remaps, s.params, s.when) for s in specs]


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def raised(path: Path, **args: str) -> LaunchError:
    with pytest.raises(LaunchError) as caught:
        planned(path, **args)
    return caught.value


# -- the same launch in three formats --------------------------------------------------------


def test_the_mimic_example_is_one_plan_in_all_three_formats(tutorial_package):
    # Creating-Launch-Files: turtlesim_mimic_launch.{py,xml,yaml}
    plans = {fmt: summary(planned(tutorial_package / f"turtlesim_mimic_launch.{fmt}")[1])
             for fmt in ("py", "xml", "yaml")}  # fmt: skip
    assert plans["py"] == plans["xml"] == plans["yaml"]
    sim1, sim2, mimic = planned(tutorial_package / "turtlesim_mimic_launch.py")[1]
    assert (sim1.node, sim2.node, mimic.node) == ("/turtlesim1/sim", "/turtlesim2/sim", "/mimic")
    assert mimic.remaps == [
        ("/input/pose", "/turtlesim1/turtle1/pose"),
        ("/output/cmd_vel", "/turtlesim2/turtle1/cmd_vel"),
    ]


EQUIVALENT = [
    (
        "arguments, let, namespaces and parameters",
        """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, SetLaunchConfiguration
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value='one'),
        SetLaunchConfiguration('rate', '2.5'),
        SetParameter(name='shared', value='3'),
        GroupAction([
            PushRosNamespace(LaunchConfiguration('ns')),
            SetRemap(src='chatter', dst='talk'),
            Node(package='ros_tutorials_topic', executable='talker', name='t',
                 parameters=[{'rate': LaunchConfiguration('rate'), 'deep': {'x': 1}}],
                 remappings=[('a', 'b')]),
        ]),
        Node(package='ros_tutorials_topic', executable='listener'),
    ])
""",
        """
launch:
- arg: {name: ns, default: one}
- let: {name: rate, value: '2.5'}
- set_parameter: {name: shared, value: '3'}
- group:
    children:
    - push_ros_namespace: {namespace: $(var ns)}
    - set_remap: {from: chatter, to: talk}
    - node:
        pkg: ros_tutorials_topic
        exec: talker
        name: t
        param:
        - {name: rate, value: $(var rate)}
        - {name: deep.x, value: 1}
        remap:
        - {from: a, to: b}
- node: {pkg: ros_tutorials_topic, exec: listener}
""",
        """<launch>
<arg name="ns" default="one"/>
<let name="rate" value="2.5"/>
<set_parameter name="shared" value="3"/>
<group>
  <push_ros_namespace namespace="$(var ns)"/>
  <set_remap from="chatter" to="talk"/>
  <node pkg="ros_tutorials_topic" exec="talker" name="t">
    <param name="rate" value="$(var rate)"/><param name="deep.x" value="1"/>
    <remap from="a" to="b"/>
  </node>
</group>
<node pkg="ros_tutorials_topic" exec="listener"/>
</launch>
""",
    ),
    (
        "timers, environment, conditions and executables",
        """
from launch import LaunchDescription
from launch.actions import ExecuteProcess, SetEnvironmentVariable, TimerAction, LogInfo
from launch.conditions import IfCondition, UnlessCondition

def generate_launch_description():
    return LaunchDescription([
        SetEnvironmentVariable('GREETING', 'hello'),
        LogInfo(msg='starting'),
        TimerAction(period=1.5, actions=[
            ExecuteProcess(cmd=['true', '--now']),
            TimerAction(period='0.5', actions=[ExecuteProcess(cmd=['false'])]),
            ExecuteProcess(cmd=['never'], condition=IfCondition('false')),
            ExecuteProcess(cmd=['echo'], condition=UnlessCondition('0')),
        ]),
    ])
""",
        """
launch:
- set_env: {name: GREETING, value: hello}
- log: {message: starting}
- timer:
    period: 1.5
    children:
    - executable: {cmd: true --now}
    - timer:
        period: '0.5'
        children:
        - executable: {cmd: 'false'}
    - executable: {cmd: never, if: 'false'}
    - executable: {cmd: echo, unless: '0'}
""",
        """<launch>
<set_env name="GREETING" value="hello"/>
<log message="starting"/>
<timer period="1.5">
  <executable cmd="true --now"/>
  <timer period="0.5"><executable cmd="false"/></timer>
  <executable cmd="never" if="false"/>
  <executable cmd="echo" unless="0"/>
</timer>
</launch>
""",
    ),
]


@pytest.mark.parametrize(("python", "yaml_text", "xml"), [c[1:] for c in EQUIVALENT],
                         ids=[c[0] for c in EQUIVALENT])  # fmt: skip
def test_python_yaml_and_xml_build_the_same_plan(tmp_path, python, yaml_text, xml):
    launches = {
        suffix: planned(write(tmp_path, f"t.launch.{suffix}", text))
        for suffix, text in (("py", python), ("yaml", yaml_text), ("xml", xml))
    }
    plans = {suffix: summary(specs) for suffix, (_, specs) in launches.items()}
    assert plans["py"] == plans["yaml"] == plans["xml"]
    messages = {suffix: launch.messages for suffix, (launch, _) in launches.items()}
    assert messages["py"] == messages["yaml"] == messages["xml"]
    envs = {suffix: [s.env for s in specs] for suffix, (_, specs) in launches.items()}
    assert envs["py"] == envs["yaml"] == envs["xml"]


def test_the_first_case_resolves_as_ros2_launch_would(tmp_path):
    _, (talker, listener) = planned(write(tmp_path, "t.launch.py", EQUIVALENT[0][1]), ns="two")
    assert talker.node == "/two/t" and listener.node is None
    assert talker.remaps == [("chatter", "talk"), ("a", "b")]  # the scope's first, as rcl reads
    assert dict(talker.params) == {"shared": 3, "rate": 2.5, "deep.x": 1}
    assert listener.params == [("shared", 3)] and listener.remaps == []


def test_timers_delay_what_they_hold(tmp_path):
    _, specs = planned(write(tmp_path, "t.launch.xml", EQUIVALENT[1][3]))
    assert [(s.command[0], s.when.delay) for s in specs] == [
        ("true", 1.5), ("false", 2.0), ("echo", 1.5),
    ]  # fmt: skip
    assert all(s.env == {"GREETING": "hello"} for s in specs)


# -- the tutorials' Python files --------------------------------------------------------------


@pytest.mark.parametrize("fmt", ["py", "yaml"])
def test_using_substitutions_main_file_includes_with_arguments(tutorial_package, fmt):
    # The YAML version's $(eval "200 == 200 and True") needs no code: no --allow-code.
    launch = resolve(tutorial_package / f"example_main_launch.{fmt}", {}, Options())
    sim, spawn, purple, pink = make_plan(launch)
    assert sim.node == "/turtlesim2/sim"
    assert spawn.command[:2] in (["/bin/sh", "-c"], ["ros2", "service"])
    assert "turtlesim2/spawn turtlesim/srv/Spawn" in " ".join(spawn.command)
    assert " ".join(purple.command).endswith("turtlesim2/sim background_r 120")
    assert " ".join(pink.command).endswith("turtlesim2/sim background_r 200")
    assert (purple.when, pink.when) == (When(), When(delay=2.0))


def test_using_substitutions_condition_and_show_args(tutorial_package):
    path = tutorial_package / "example_substitutions_launch.py"
    _, specs = planned(path)  # use_provided_red defaults to False: no change after 2 s
    assert [s.node for s in specs] == ["/turtlesim1/sim", None, None]
    _, specs = planned(path, turtlesim_ns="turtlesim3", use_provided_red="True")
    assert specs[0].node == "/turtlesim3/sim" and specs[-1].when == When(delay=2.0)
    names = [(a.name, a.default, a.description) for a in describe_args(path)]
    assert names == [("turtlesim_ns", "turtlesim1", ""), ("use_provided_red", "False", ""),
                     ("new_background_r", "200", "")]  # fmt: skip


def test_show_args_prints_as_ros2_launch(tutorial_package):
    out = ok("ros2", "launch", "launch_tutorial", "example_substitutions_launch.py", "--show-args")
    assert out.splitlines()[:5] == [
        "Arguments (pass arguments as '<name>:=<value>'):",
        "",
        "    'turtlesim_ns':",
        "        no description given",
        "        (default: 'turtlesim1')",
    ]


def test_using_event_handlers_becomes_processes_and_steps_that_wait(tutorial_package, monkeypatch):
    path = tutorial_package / "example_event_handlers_launch.py"
    # The page's note: EnvironmentVariable('USER'). Set for this test only: the session's
    # environment must stay as the warm-start server imported it (tests/warm.py).
    monkeypatch.setenv("USER", os.environ.get("USER", "learner"))
    launch, specs = planned(path, use_provided_red="True")
    sim, spawn, purple, pink = specs
    assert sim.when == When()
    assert spawn.when == When("start", 0)  # OnProcessStart(turtlesim_node)
    assert purple.when == When("exit", 1)  # OnExecutionComplete(spawn_turtle)
    assert pink.when == When("exit", 1, 2.0)  # ... then TimerAction(2.0)
    logs = {(s.kind, s.text, s.when) for s in launch.steps if s.kind != "call"}
    assert ("log", "Turtlesim started, spawning turtle", When("start", 0)) in logs
    assert ("log", "Spawn finished", When("exit", 1)) in logs
    assert ("shutdown", "Window closed", When("exit", 0)) in logs
    # EnvironmentVariable('USER') is read when the turtlesim exits, as ros2 launch reads it
    (closed,) = [s for s in launch.steps if s.kind == "call" and s.when == When("exit", 0)]
    (said,) = closed.call({"returncode": 0, "pid": 1})
    assert said.text == f"{os.environ['USER']} closed the turtlesim window"
    calls = sorted(s.when.event for s in launch.steps if s.kind == "call")
    assert calls == ["exit", "shutdown", "stdout"]  # USER, the event's reason, OnProcessIO's
    # The functions run when their event happens, with its values.
    (shutdown,) = [s for s in launch.steps if s.kind == "call" and s.when.event == "shutdown"]
    (said,) = shutdown.call({"reason": "Window closed"})
    assert said.text == "Launch was asked to shutdown: Window closed"
    (io,) = [s for s in launch.steps if s.when.event == "stdout"]
    (said,) = io.call({"text": "  response: ok \n", "pid": 1})
    assert said.text == 'Spawn request says "response: ok"'


def test_multisim_launch_py_is_turtlesims_two_simulators():
    out = ok("ros2", "launch", "turtlesim", "multisim.launch.py", "--print")
    nodes = [line.split("]")[0][1:] for line in out.splitlines() if line.startswith("[")]
    assert nodes == ["turtlesim1/turtlesim_node", "turtlesim2/turtlesim_node"]
    assert "mimic" not in out and out.count("output=screen") == 2


# -- includes across formats ------------------------------------------------------------------


def test_python_includes_xml_includes_yaml(tmp_path):
    write(tmp_path, "leaf.launch.yaml", """
launch:
- arg: {name: who}
- node: {pkg: ros_tutorials_topic, exec: listener, name: $(var who)}
""")  # fmt: skip
    write(tmp_path, "middle.launch.xml", """<launch>
<arg name="prefix"/>
<push_ros_namespace namespace="xml"/>
<include file="leaf.launch.yaml"><arg name="who" value="$(var prefix)_leaf"/></include>
<timer period="1"><log message="from xml"/></timer>
</launch>""")  # fmt: skip
    top = write(tmp_path, "top.launch.py", """
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription, GroupAction
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.actions import PushRosNamespace
from launch_xml.launch_description_sources import XMLLaunchDescriptionSource

def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('py'),
            IncludeLaunchDescription(
                XMLLaunchDescriptionSource(
                    PathJoinSubstitution([ThisLaunchFileDir(), 'middle.launch.xml'])),
                launch_arguments={'prefix': 'deep'}.items()),
        ]),
        IncludeLaunchDescription(AnyLaunchDescriptionSource('leaf.launch.yaml'),
                                 launch_arguments=[('who', 'top')]),
    ])
""")  # fmt: skip
    launch, (deep, shallow) = planned(top)
    assert (deep.node, shallow.node) == ("/py/xml/deep_leaf", "/top")
    assert deep.where.startswith(str(tmp_path / "leaf.launch.yaml"))
    assert [(s.text, s.when) for s in launch.steps] == [("from xml", When(delay=1.0))]


def test_xml_and_yaml_include_python(tmp_path):
    write(tmp_path, "inner.launch.py", """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('name', default_value='x'),
        Node(package='ros_tutorials_topic', executable='talker', name=LaunchConfiguration('name')),
    ])
""")  # fmt: skip
    xml = write(
        tmp_path,
        "outer.launch.xml",
        """<launch><group><push_ros_namespace namespace="a"/>
<include file="inner.launch.py"><arg name="name" value="from_xml"/></include></group></launch>""",
    )
    yaml_file = write(
        tmp_path, "outer.launch.yaml", "launch:\n- include: {file: inner.launch.py}\n"
    )
    assert [s.node for s in planned(xml)[1]] == ["/a/from_xml"]
    assert [s.node for s in planned(yaml_file)[1]] == ["/x"]


# -- errors: one clear line, or the launch file's own traceback -------------------------------


def test_a_name_this_launcher_lacks_is_one_line_at_the_import(tmp_path):
    path = write(tmp_path, "t.launch.py", "from launch import LaunchDescription\n"
                 "from launch.actions import OpaqueCoroutine\n")  # fmt: skip
    message = str(raised(path))
    assert message.startswith(f"{path}:2: launch.actions.OpaqueCoroutine is not in this ")
    assert "TimerAction" in message and "\n" not in message


def test_a_launch_file_that_raises_shows_its_own_traceback(tmp_path):
    path = write(tmp_path, "t.launch.py", """
from launch import LaunchDescription
from launch.actions import OpaqueFunction

def broken(context):
    return [1 / 0]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=broken)])
""")  # fmt: skip
    error = raised(path)
    assert isinstance(error, LaunchFileRaised)
    assert str(error) == f"{path}:6: the launch file raised ZeroDivisionError: division by zero"
    assert f'File "{path}", line 6, in broken' in error.traceback
    assert "launcher" not in error.traceback and "/launch/" not in error.traceback


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("def generate_launch_description(:\n", ":1: SyntaxError: "),
        ("x = 1\n", ": a Python launch file defines generate_launch_description()"),
        ("def generate_launch_description():\n    return [1]\n", "returned list, not a Launch"),
        (
            "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
            "def generate_launch_description():\n    return LaunchDescription([\n"
            "        Node(package='turtlesim', executable='nope')])\n",
            ":5: package 'turtlesim' has no executable 'nope'",
        ),
        (
            "from launch import LaunchDescription\nfrom launch.actions import"
            " DeclareLaunchArgument\ndef generate_launch_description():\n"
            "    return LaunchDescription([DeclareLaunchArgument('must')])\n",
            ":4: argument 'must' is required: pass must:=<value>",
        ),
    ],
    ids=["syntax", "no-function", "not-a-description", "unknown-executable", "required-arg"],
)
def test_python_launch_file_errors_name_the_file_and_line(tmp_path, text, expected):
    path = write(tmp_path, "t.launch.py", text)
    assert expected in str(raised(path))


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("launch:\n- node: {pkg: a\n", ":3:1: malformed YAML"),
        ("nodes: []\n", ":1: a YAML launch file is one mapping, 'launch:' a list"),
        ("launch:\n- node: x\n", ":2: 'node:' takes attributes"),
        ("launch:\n- {node: {}, arg: {}}\n", ":2: each entity is one tag"),
        ("launch:\n- nodes: {pkg: a}\n", ":2: unknown tag <nodes> in <launch> (ROS 2 format)"),
        ("launch:\n- node: {pkg: a, exec: b, colour: red}\n", ":2: unknown attribute 'colour'"),
        ("launch:\n- timer:\n    children: []\n", ":2: <timer> needs a 'period'"),
    ],
    ids=["malformed", "no-launch", "scalar", "two-tags", "unknown-tag", "unknown-attr", "timer"],
)
def test_yaml_errors_name_the_file_and_line(tmp_path, text, expected):
    path = write(tmp_path, "t.launch.yaml", text)
    assert f"{path}{expected}" in str(raised(path))


def test_an_undeclared_command_line_argument_is_a_launch_configuration(tutorial_package):
    # ros2 launch sets every given argument as a launch configuration; nothing reads this
    # one, so it is probably a typo: one warning line, and the launch goes on.
    result = run("ros2", "launch", "launch_tutorial", "example_substitutions_launch.py",
                 "turtlesim_nss:=x", "--print")  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert "declares no argument 'turtlesim_nss' and does not read it" in result.stderr
    assert "[turtlesim1/sim]" in result.stdout


# -- launch_xml's own cases (launch_xml/test, launch_yaml/test), in this launcher's terms ------


def test_append_env_as_launch_xml_tests_it(tmp_path, monkeypatch):
    monkeypatch.delenv("MY_ENV_VAR", raising=False)
    monkeypatch.setenv("MY_OTHER_ENV_VAR", "start")
    path = write(tmp_path, "t.launch.xml", """<launch>
<append_env name="MY_ENV_VAR" value="asd"/>
<append_env name="MY_ENV_VAR" value="zxc" separator="|"/>
<append_env name="MY_OTHER_ENV_VAR" value="jkl" prepend="false"/>
<append_env name="MY_OTHER_ENV_VAR" value="qwe" prepend="yes"/>
<append_env name="MY_OTHER_ENV_VAR" value="rty" prepend="true" separator="|"/>
<executable cmd="true"/>
</launch>""")  # fmt: skip
    (spec,) = planned(path)[1]
    assert spec.env == {"MY_ENV_VAR": "asd|zxc", "MY_OTHER_ENV_VAR": f"rty|qwe{os.pathsep}start"
                        f"{os.pathsep}jkl"}  # fmt: skip


def test_reset_keeps_only_what_it_is_told(tmp_path):
    path = write(tmp_path, "t.launch.yaml", """
launch:
- let: {name: foo, value: FOO}
- let: {name: bar, value: BAR}
- reset:
    keep:
    - {name: bar, value: $(var bar)}
    - {name: baz, value: BAZ}
- executable: {cmd: echo $(var bar) $(var baz)}
- executable: {cmd: echo $(var foo)}
""")  # fmt: skip
    assert "argument 'foo' is not declared here (declared: bar, baz)" in str(raised(path))
    text = path.read_text().replace("- executable: {cmd: echo $(var foo)}\n", "")
    (spec,) = planned(write(tmp_path, "t.launch.yaml", text))[1]
    assert spec.command == ["echo", "BAR", "BAZ"]


def test_deprecated_launch_file_says_so(tmp_path):
    path = write(tmp_path, "t.launch.xml", '<launch deprecated="use other.launch.xml"/>')
    # ros2 launch's own words: [WARNING] [launch]: launch file [PATH] is deprecated: MESSAGE
    assert resolved(path).warnings == [f"launch file [{path}] is deprecated: use other.launch.xml"]


@pytest.mark.parametrize("fmt", ["xml", "yaml", "py"])
def test_ros2_parameter_values_are_typed_as_yaml_in_every_format(tmp_path, fmt):
    # launch_ros reads a parameter's text as YAML: [2, 5, 8] is a list, not a string.
    values = {"ints": "[2, 5, 8]", "rate": "2.5", "on": "true", "name": "turtle", "n": "7"}
    text = {
        "xml": "<launch><node pkg='ros_tutorials_topic' exec='talker'>"
        + "".join(f"<param name='{k}' value='{v}'/>" for k, v in values.items())
        + "</node></launch>",
        "yaml": "launch:\n- node:\n    pkg: ros_tutorials_topic\n    exec: talker\n    param:\n"
        + "".join(f"    - {{name: {k}, value: '{v}'}}\n" for k, v in values.items()),
        "py": "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
        "def generate_launch_description():\n    return LaunchDescription([Node(package="
        f"'ros_tutorials_topic', executable='talker', parameters=[{values!r}])])\n",
    }[fmt]
    (spec,) = planned(write(tmp_path, f"t.launch.{fmt}", text))[1]
    assert dict(spec.params) == {"ints": [2, 5, 8], "rate": 2.5, "on": True, "name": "turtle",
                                 "n": 7}  # fmt: skip


def test_argument_names_with_parts_can_be_set_on_the_command_line(tmp_path):
    path = write(tmp_path, "t.launch.yaml", """
launch:
- arg: {name: perception/enable, default: 'true'}
- executable: {cmd: echo $(var perception/enable)}
""")  # fmt: skip
    out = ok("ros2", "launch", str(path), "perception/enable:=false", "--print")
    assert "command: echo false" in out


@pytest.mark.parametrize(
    ("name", "text"),
    [
        ("t.launch.xml", '<launch><executable cmd="echo $HOME | tr a-z A-Z" shell="true" '
                         'emulate_tty="true"/></launch>'),
        ("t.launch.yaml", "launch:\n- executable:\n    cmd: echo $HOME | tr a-z A-Z\n"
                          "    shell: 'true'\n    emulate_tty: 'true'\n"),
    ],
)  # fmt: skip
def test_executable_takes_shell_and_emulate_tty_as_launch_xml_does(tmp_path, monkeypatch, name,
                                                                   text):  # fmt: skip
    """launch's ExecuteProcess.parse reads <executable shell emulate_tty> (launch_xml's own
    test_include uses both): the command is one shell line, and the process gets rcutils'
    colours."""
    monkeypatch.delenv("RCUTILS_COLORIZED_OUTPUT", raising=False)
    (spec,) = planned(write(tmp_path, name, text))[1]
    assert spec.command[-1] == "echo $HOME | tr a-z A-Z"
    assert spec.command[:-1] == ["/bin/sh", "-c"]
    assert spec.env.get("RCUTILS_COLORIZED_OUTPUT") == "1"
