"""launch.frontend (issue 34): the markup front-ends parse into the actions the Python API
builds, each tag by the one parse method its action exposes, as ros2/launch's launch_xml and
launch_yaml tests load them (Parser.load -> parse_description -> the actions, executed in a
LaunchContext); and the ROS 2 tags the launcher runs through those actions (<include>,
<set_parameter>, <param>, composable nodes)."""

from __future__ import annotations

import io
import textwrap
from pathlib import Path

import pytest

from launch.actions import (
    AppendEnvironmentVariable,
    LogInfo,
    ResetLaunchConfigurations,
    SetEnvironmentVariable,
    SetLaunchConfiguration,
    UnsetEnvironmentVariable,
)
from launch.frontend import Entity, Parser, expose_action
from launch.launch_context import LaunchContext
from launch.utilities import perform_substitutions
from launch_ros.actions import PushRosNamespace, SetParameter, SetRemap
from launcher import LaunchError
from launcher.loading import resolve
from launcher.scope import Options


def load(text: str, name: str | None = None):
    """Parser.load of a launch file's text, as launch_xml's tests do (a StringIO)."""
    stream = io.StringIO(textwrap.dedent(text))
    if name:
        stream.name = name
    root, parser = Parser.load(stream)
    return parser.parse_description(root)


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


def test_reset_keeps_what_it_is_told_as_launch_xmls_test():  # launch_xml's test_reset.py
    ld = load("""\
        <launch>
            <let name="foo" value="FOO"/>
            <let name="bar" value="BAR"/>
            <reset>
                <keep name="bar" value="$(var bar)"/>
                <keep name="baz" value="BAZ"/>
            </reset>
        </launch>
        """)
    assert isinstance(ld.entities[2], ResetLaunchConfigurations)
    context = LaunchContext()
    for entity in ld.entities:
        entity.execute(context)
    assert context.launch_configurations == {"bar": "BAR", "baz": "BAZ"}
    # The Python API's spelling of the same action.
    ResetLaunchConfigurations({"baz": "again"}).execute(context)
    assert context.launch_configurations == {"baz": "again"}


def test_let_and_var_as_launch_xmls_test():  # launch_xml/test/launch_xml/test_let_var.py
    ld = load("""\
        <launch>
            <let name="var1" value="asd"/>
            <let name="var2" value="2 $(var var1)"/>
        </launch>
        """)
    context = LaunchContext()
    assert len(ld.entities) == 2
    assert all(isinstance(entity, SetLaunchConfiguration) for entity in ld.entities)
    ld.entities[0].execute(context)
    ld.entities[1].execute(context)
    assert context.launch_configurations["var1"] == "asd"
    assert context.launch_configurations["var2"] == "2 asd"


def test_log_as_launch_xmls_and_launch_yamls_test():  # test_log.py of both
    xml = load('<launch>\n    <log message="Hello world!" />\n</launch>\n')
    yaml = load("launch:\n- log:\n    message: Hello world!\n", "t.launch.yaml")
    for ld in (xml, yaml):
        (log_info,) = ld.entities
        assert isinstance(log_info, LogInfo)
        assert perform_substitutions(LaunchContext(), log_info.msg) == "Hello world!"


def test_environment_tags_as_launch_xmls_tests():  # test_set_env, test_unset_env, append_env
    ld = load("""\
        <launch>
            <set_env name="MY_ENV_VAR" value="my_value"/>
            <append_env name="MY_PATH" value="/b" prepend="yes" separator=":"/>
            <unset_env name="MY_ENV_VAR" if="true"/>
        </launch>
        """)
    set_env, append_env, unset_env = ld.entities
    assert isinstance(set_env, SetEnvironmentVariable)
    assert isinstance(append_env, AppendEnvironmentVariable)
    assert isinstance(unset_env, UnsetEnvironmentVariable)
    context = LaunchContext()
    set_env.visit(context)
    assert context.environment["MY_ENV_VAR"] == "my_value"
    unset_env.visit(context)
    assert "MY_ENV_VAR" not in context.environment


def test_launch_ros_tags_build_launch_ros_actions():
    ld = load(
        """\
        launch:
        - push_ros_namespace: {namespace: robot}
        - set_remap: {from: chatter, to: news}
        - set_parameter: {name: rate, value: "2"}
        """,
        "t.launch.yaml",
    )
    push, remap, parameter = ld.entities
    assert isinstance(push, PushRosNamespace) and isinstance(remap, SetRemap)
    assert isinstance(parameter, SetParameter)
    context = LaunchContext()
    for action in ld.entities:
        action.visit(context)
    assert context.ros_namespace == "/robot"
    assert context.ros_remaps == [("chatter", "news")]
    assert context.ros_params == [("rate", 2)]  # typed as launch_ros types it: by YAML


def test_a_condition_is_the_actions_condition():
    ld = load('<launch><let name="a" value="1" unless="$(var off)"/></launch>')
    context = LaunchContext()
    context.launch_configurations["off"] = "true"
    ld.entities[0].visit(context)
    assert "a" not in context.launch_configurations


def test_an_entity_reads_typed_attributes():
    root, _parser = Parser.load(io.StringIO('<launch><timer period="2.5" flag="true"/></launch>'))
    assert isinstance(root, Entity) and root.type_name == "launch"
    (timer,) = root.children
    assert timer.get_attr("period", data_type=float) == 2.5
    assert timer.get_attr("flag", data_type=bool) is True
    assert timer.get_attr("missing", optional=True) is None
    with pytest.raises(AttributeError):
        timer.get_attr("missing")


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('<launch><let name="a" value="b" valeu="c"/></launch>', "unknown attribute 'valeu'"),
        ("<launch><no_such_tag/></launch>", "unknown tag <no_such_tag>"),
        ("<launch><let name='a'/></launch>", "needs a 'value' attribute"),
    ],
)
def test_what_no_parse_method_reads_is_refused_at_its_line(text, message):
    with pytest.raises((LaunchError, AttributeError), match=message):
        load(text, "bad.launch.xml")


def test_node_and_executable_as_launch_xmls_and_launch_ross_tests():  # test_executable, test_node
    from launch.actions import ExecuteProcess
    from launch_ros.actions import Node

    ld = load("""\
        <launch>
            <let name="who" value="talker"/>
            <node pkg="ros_tutorials_topic" exec="talker" name="$(var who)" namespace="ns"
                  args="-a 'b c'" respawn="true" respawn_delay="2">
                <param name="rate" value="2.5"/>
                <param name="group"><param name="x" value="1"/></param>
                <remap from="chatter" to="talk"/>
                <remap from="a" to="b" if="false"/>
                <env name="A" value="$(var who)"/>
            </node>
            <executable cmd="echo hi" args="there" name="say" cwd="/tmp" output="screen"
                        on_exit="shutdown"/>
        </launch>
        """)
    let, node, executable = ld.entities
    assert type(node) is Node and type(executable) is ExecuteProcess
    context = LaunchContext()
    let.execute(context)
    decl = node.process_decl(context)
    assert (decl.name, decl.namespace, decl.args) == ("talker", "/ns", ["-a", "b c"])
    assert decl.params == [("rate", 2.5), ("group.x", 1)] and decl.remaps == [("chatter", "talk")]
    assert decl.env == {"A": "talker"} and decl.respawn and decl.respawn_delay == 2.0
    decl = executable.process_decl(context)
    assert (decl.cmd, decl.label, decl.cwd, decl.output) == (
        ["echo", "hi", "there"], "say", "/tmp", "screen")  # fmt: skip
    assert decl.required


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('<node pkg="a" exec="b" respawn_delay="soon"/>',
         ":2: 'respawn_delay' must be a non-negative number, not 'soon'"),
        ('<node pkg="a" exec="b" colour="red"/>', ":2: unknown attribute 'colour' on <node>"),
        ('<node pkg="a" exec=" "/>', ":2: <node exec> is empty"),
        ("<executable cmd=\"echo 'a\"/>", ":2: cmd=\"echo 'a\": No closing quotation"),
        ('<executable name="x"/>', ":2: <executable> needs a non-empty 'cmd'"),
        ('<executable cmd="x" output=""/>', ":2: output=''; use one of screen, log, both"),
        ('<load_composable_node><composable_node pkg="p" plugin="p::X"/></load_composable_node>',
         ":2: <load_composable_node> needs a 'target' attribute"),
        ('<executable cmd="sleep 1" on_exit="restart"/>',
         ":2: on_exit='restart' is not supported; use 'shutdown'"),
    ],
)  # fmt: skip
def test_node_and_executable_attributes_are_checked_at_their_line(text, message):
    with pytest.raises(LaunchError, match=message):
        ld = load(f"<launch>\n{text}\n</launch>\n", "bad.launch.xml")
        ld.entities[0].process_decl(LaunchContext())


def test_container_tags_build_launch_ros_containers():  # launch_ros's test_composable_node
    from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes

    ld = load("""\
        <launch>
            <node_container pkg="rclcpp_components" exec="component_container" name="box"
                            namespace="ns">
                <composable_node pkg="demo" plugin="demo::Talker" name="talker">
                    <param name="rate" value="2"/>
                    <remap from="chatter" to="talk"/>
                    <extra_arg name="use_intra_process_comms" value="true"/>
                </composable_node>
                <composable_node pkg="demo" plugin="demo::Off" unless="true"/>
            </node_container>
            <load_composable_node target="/ns/box">
                <composable_node pkg="demo" plugin="demo::Listener"/>
            </load_composable_node>
        </launch>
        """)
    container, load_nodes = ld.entities
    assert isinstance(container, ComposableNodeContainer)
    assert isinstance(load_nodes, LoadComposableNodes)
    talker, off = container.composable_node_descriptions
    context = LaunchContext()
    decl = talker.component_decl(context, "/ns")
    assert (decl.name, decl.namespace, decl.plugin) == ("talker", "/ns", "demo::Talker")
    assert decl.params == [("rate", 2)] and decl.remaps == [("chatter", "talk")]
    assert decl.extra_args == [("use_intra_process_comms", "true")]
    assert not off.condition.evaluate(context)
    (listener,) = load_nodes.composable_node_descriptions
    assert listener.component_decl(context, "/").plugin == "demo::Listener"


def test_a_tag_is_exposed_once():
    from launch.frontend.expose import action_parse_methods

    known = action_parse_methods["let"]
    with pytest.raises(RuntimeError, match="two action parse methods"):
        expose_action("let")(lambda entity, parser: (LogInfo, {}))
    assert action_parse_methods["let"] is known


def test_a_file_no_front_end_reads_is_one_error(tmp_path):
    path = write(tmp_path, "t.launch.xml", "<launch><let name='a'\n")
    with pytest.raises(LaunchError, match="no front-end reads it"):
        Parser.load(path)


# -- the launcher runs the ROS 2 tags through the same actions ----------------------------------


def test_an_include_sets_every_given_argument_and_checks_required_ones(tmp_path):
    write(
        tmp_path,
        "inner.launch.xml",
        """\
        <launch>
            <arg name="needed"/>
            <executable cmd="echo $(var needed) $(var extra)"/>
        </launch>
        """,
    )
    main = write(
        tmp_path,
        "main.launch.xml",
        """\
        <launch>
            <include file="inner.launch.xml">
                <arg name="needed" value="a"/>
                <arg name="extra" value="b"/>
            </include>
        </launch>
        """,
    )
    assert resolve(main, {}, Options()).nodes[0].cmd == ["echo", "a", "b"]
    missing = write(
        tmp_path, "missing.launch.xml", '<launch><include file="inner.launch.xml"/></launch>\n'
    )
    with pytest.raises(LaunchError, match="needed"):
        resolve(missing, {}, Options())


@pytest.mark.parametrize(("hello", "said"), [("true", "hello"), ("false", "goodbye")])
def test_an_include_argument_may_have_a_condition(tmp_path, hello, said):
    # as ros_tutorials_parameter/launch/combine.launch.xml passes talker_str
    write(tmp_path, "inner.launch.xml", '<launch><executable cmd="echo $(var word)"/></launch>')
    main = write(
        tmp_path,
        "main.launch.xml",
        """\
        <launch>
            <arg name="hello" default="true"/>
            <include file="inner.launch.xml">
                <arg name="word" value="hello" if="$(var hello)"/>
                <arg name="word" value="goodbye" unless="$(var hello)"/>
            </include>
        </launch>
        """,
    )
    assert resolve(main, {"hello": hello}, Options()).nodes[0].cmd == ["echo", said]


def test_node_params_and_set_parameter_are_launch_ros_parameters(tmp_path):
    params = write(tmp_path, "p.yaml", "/**:\n  ros__parameters:\n    a: 1\n")
    path = write(
        tmp_path,
        "t.launch.xml",
        f"""\
        <launch>
            <set_parameter name="use_sim_time" value="true"/>
            <node pkg="ros_tutorials_topic" exec="talker">
                <param name="text" value="1" type="str"/>
                <param name="group"><param name="rate" value="2"/></param>
                <param from="{params}"/>
                <remap from="chatter" to="news"/>
            </node>
        </launch>
        """,
    )
    (node,) = resolve(path, {}, Options()).nodes
    assert node.params == [("use_sim_time", True), ("text", "1"), ("group.rate", 2)]
    assert node.params_files == [str(params)]
    assert node.remaps == [("chatter", "news")]


def test_a_bad_params_file_is_refused_at_the_params_line(tmp_path):
    path = write(
        tmp_path,
        "t.launch.xml",
        """\
        <launch>
            <node pkg="ros_tutorials_topic" exec="talker">

                <param from="nowhere.yaml"/>
            </node>
        </launch>
        """,
    )
    with pytest.raises(LaunchError, match=r"t\.launch\.xml:4: "):
        resolve(path, {}, Options())


def test_timer_as_launch_xmls_test():  # launch_xml/test/launch_xml/test_timer.py
    from launch.actions import TimerAction
    from launch.frontend.frontend_text import FrontendText

    ld = load('<launch>\n<timer period="5">\n  <let name="a" value="b"/>\n</timer>\n</launch>\n')
    (timer,) = ld.entities
    assert isinstance(timer, TimerAction) and timer.period == 5.0 and len(timer.actions) == 1
    ld = load('<launch><timer period="$(var my_period 5)"><log message="x"/></timer></launch>')
    (timer,) = ld.entities
    assert isinstance(timer.period, list) and isinstance(timer.period[0], FrontendText)


def test_group_as_launch_xmls_test():  # launch_xml/test/launch_xml/test_group.py
    from launch.actions import GroupAction

    ld = load("""\
        <launch>
            <let name="foo" value="FOO"/>
            <let name="bar" value="BAR"/>
            <group scoped="True" forwarding="False">
                <keep name="bar" value="$(var bar)"/>
                <keep name="baz" value="BAZ"/>
                <let name="var1" value="asd"/>
            </group>
        </launch>
        """)
    assert isinstance(ld.entities[2], GroupAction)
    context = LaunchContext()
    for entity in ld.entities[:2]:
        entity.visit(context)
    group = ld.entities[2]
    assert len(group.actions) == 1 and isinstance(group.actions[0], SetLaunchConfiguration)
    group.visit(context)  # scoped: nothing it sets is left after it
    assert context.launch_configurations == {"foo": "FOO", "bar": "BAR"}


def test_arg_and_include_build_their_actions():
    from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription

    ld = load("""\
        <launch>
            <arg name="mode" default="fast" description="how">
                <choice value="fast"/><choice value="slow"/>
            </arg>
            <include file="other.launch.xml"><arg name="x" value="$(var mode)"/></include>
        </launch>
        """)
    arg, include = ld.entities
    assert isinstance(arg, DeclareLaunchArgument) and isinstance(include, IncludeLaunchDescription)
    assert (arg.name, arg.choices) == ("mode", ["fast", "slow"])
    assert arg.description == "how. Valid choices are: ['fast', 'slow']"  # as ros2 launch
    context = LaunchContext()
    arg.visit(context)
    assert context.launch_configurations["mode"] == "fast"
    ((name, value),) = include.launch_arguments
    assert name == "x" and perform_substitutions(context, value) == "fast"
