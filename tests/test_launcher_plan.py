"""The launcher without processes: parse, resolve and plan, both formats, every error case."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

from launcher import LaunchError
from launcher.loading import describe_args, resolve
from launcher.plan import make_plan, ros_value
from launcher.scope import Options
from ros_tutorials_common import packages

TOPIC_LAUNCH = Path(packages.package_dirs()["ros_tutorials_topic"]) / "launch"


def plan(tmp_path: Path, xml: str, name: str = "test.launch", allow_code=False, **args):
    path = tmp_path / name
    path.write_text(xml)
    return make_plan(resolve(path, args, Options(allow_code=allow_code)))


def error(tmp_path: Path, xml: str, name: str = "test.launch", **args) -> str:
    with pytest.raises(LaunchError) as caught:
        plan(tmp_path, xml, name, **args)
    return str(caught.value)


def ros1(body: str) -> str:
    return f"<launch>\n{body}\n</launch>\n"


def write_ros1(tmp_path: Path, name: str, body: str) -> None:
    """A ROS 1 launch file beside the test's own, for it to include."""
    (tmp_path / name).write_text(ros1(body))


def node1(
    name: str = "pub", type_: str = "topic_publisher", extra: str = "", body: str = ""
) -> str:
    return f'<node pkg="ros_tutorials_topic" type="{type_}" name="{name}" {extra}>{body}</node>'


def params(spec) -> dict:
    return dict(spec.params)


# -- parsing ---------------------------------------------------------------------------------


def test_malformed_xml_is_reported_with_file_line_and_column(tmp_path):
    message = error(tmp_path, "<launch>\n  <node pkg='a'\n</launch>")
    assert message.startswith(f"{tmp_path / 'test.launch'}:3:1: malformed XML")


def test_entity_bombs_and_external_entities_are_refused(tmp_path):
    bomb = (
        '<?xml version="1.0"?>\n<!DOCTYPE lolz [<!ENTITY lol "lol">'
        '<!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">]>\n<launch>&lol2;</launch>'
    )
    assert "DOCTYPE and entity declarations are not allowed" in error(tmp_path, bomb)
    external = '<!DOCTYPE launch [<!ENTITY x SYSTEM "file:///etc/passwd">]><launch>&x;</launch>'
    assert "not allowed" in error(tmp_path, external)


def test_the_root_must_be_launch(tmp_path):
    assert "root element must be <launch>" in error(tmp_path, "<group/>")


def test_mixing_both_formats_in_one_file_is_an_error(tmp_path):
    xml = ros1(node1() + '\n<node pkg="ros_tutorials_topic" exec="subscriber"/>')
    assert (
        "mixes ROS 1 syntax (line 2: <node type=...>) and ROS 2 syntax (line 3: <node exec=...>)"
    ) in error(tmp_path, xml)


# -- packages and executables ----------------------------------------------------------------


def test_book_type_and_ros2_exec_name_the_same_command(tmp_path):
    by_type = plan(tmp_path, ros1(node1(type_="topic_publisher")))[0]
    by_module = plan(tmp_path, ros1(node1(type_="publisher")))[0]
    by_script = plan(tmp_path, ros1(node1(type_="talker.py")))[0]
    assert by_type.command == by_module.command
    # A lesson starts where the project handles rclpy's shutdown race (lesson_scripts).
    start = [sys.executable, "-m", "ros_tutorials_common.lesson_scripts"]
    assert by_type.command[:4] == [*start, "ros_tutorials_topic.publisher"]
    assert by_script.command[:4] == [*start, "ros_tutorials_topic.talker"]


def test_executables_are_discovered_from_modules_and_console_scripts():
    found = packages.executables("ros_tutorials_topic")
    for name in ("publisher", "subscriber", "talker", "listener", "topic_publisher"):
        assert name in found
    assert "__init__" not in found and "ros_tutorials_common" not in packages.runnable_packages()


def test_unknown_package_and_executable_list_the_known_ones(tmp_path):
    message = error(tmp_path, ros1('<node pkg="nope" type="x" name="n"/>'))
    assert message.startswith(f"{tmp_path / 'test.launch'}:2: unknown package 'nope'")
    assert "ros_tutorials_topic" in message
    message = error(tmp_path, ros1(node1(type_="nope")))
    assert "has no executable 'nope'; it has: " in message
    assert ", listener, " in message and ", publisher, " in message


def test_node_name_namespace_remaps_and_params_become_ros_arguments(tmp_path):
    body = '<remap from="ros_tutorial_msg" to="other"/><param name="rate" value="5"/>'
    spec = plan(tmp_path, ros1(f'<group ns="robot">{node1(body=body)}</group>'))[0]
    assert spec.label == "robot/pub" and spec.node == "/robot/pub"
    assert spec.command[4:] == [
        "--ros-args", "-r", "__node:=pub", "-r", "__ns:=/robot",
        "-r", "ros_tutorial_msg:=other", "-p", "rate:=5",
    ]  # fmt: skip


def test_parameter_values_are_quoted_so_rcl_reads_the_right_type():
    assert ros_value(5) == "5" and ros_value(2.5) == "2.5" and ros_value(True) == "true"
    assert ros_value("hello world") == "hello world"
    assert (
        ros_value("5") == '"5"' and ros_value("true") == '"true"' and ros_value("a: b") == '"a: b"'
    )
    assert ros_value([1, 2]) == "[1, 2]"


# -- ROS 1 format ----------------------------------------------------------------------------


def test_union_launch_runs_two_pairs_in_two_namespaces():
    specs = make_plan(resolve(TOPIC_LAUNCH / "union.launch", {}))
    assert [spec.node for spec in specs] == [
        "/ns1/topic_publisher", "/ns1/topic_subscriber",
        "/ns2/topic_publisher", "/ns2/topic_subscriber",
    ]  # fmt: skip
    assert all(spec.output == "log" and not spec.respawn for spec in specs)
    assert "__ns:=/ns2" in specs[3].command


def test_ros2_union_launch_plans_the_same_commands_as_the_book_file():
    book = make_plan(resolve(TOPIC_LAUNCH / "union.launch", {}))
    ros2 = make_plan(resolve(TOPIC_LAUNCH / "union.launch.xml", {}))
    assert [spec.command for spec in ros2] == [spec.command for spec in book]
    first = make_plan(resolve(TOPIC_LAUNCH / "union_no_groups.launch", {}))
    first2 = make_plan(resolve(TOPIC_LAUNCH / "union_no_groups.launch.xml", {}))
    assert [spec.node for spec in first] == [spec.node for spec in first2] == [
        "/topic_publisher1", "/topic_subscriber1", "/topic_publisher2", "/topic_subscriber2",
    ]  # fmt: skip


def test_every_shipped_launch_file_resolves():
    for package in packages.package_dirs():
        for path in packages.launch_files(package):
            launch = resolve(path, {})
            if all(packages.executables(node.package or "") for node in launch.nodes):
                assert make_plan(launch), path


def test_args_defaults_command_line_values_and_errors(tmp_path):
    xml = ros1(
        '<arg name="who" default="pub" doc="node name"/>\n<arg name="fixed" value="1"/>\n'
        + node1(name="$(arg who)")
    )
    assert plan(tmp_path, xml)[0].node == "/pub"
    assert plan(tmp_path, xml, who="other")[0].node == "/other"
    message = error(tmp_path, xml, nobody="x")
    assert "no argument named nobody is declared (declared: fixed, who)" in message
    assert "'fixed' has a fixed value and cannot be set" in error(tmp_path, xml, fixed="2")
    required = ros1('<arg name="who"/>\n' + node1(name="$(arg who)"))
    assert (  # where it is used: roslaunch fails there, not at the declaration
        "test.launch:3: argument 'who' is required (declared at line 2 without a value): "
        "pass who:=<value>"
    ) in error(tmp_path, required)
    undeclared = ros1(node1(name="$(arg who)"))
    assert "argument 'who' is not declared here (declared: none)" in error(tmp_path, undeclared)


def test_if_and_unless_take_true_false_1_0_in_any_case(tmp_path):
    xml = ros1(
        '<arg name="hello" default="True"/>\n'
        f'<group if="$(arg hello)">{node1("yes")}</group>\n'
        f'<group unless="$(arg hello)">{node1("no")}</group>\n' + node1("one", extra='if="1"')
    )
    assert [s.label for s in plan(tmp_path, xml)] == ["yes", "one"]
    assert [s.label for s in plan(tmp_path, xml, hello="0")] == ["no", "one"]
    assert "'if' must be true, false, 1 or 0, not 'maybe'" in error(tmp_path, xml, hello="maybe")
    both = ros1(node1(extra='if="1" unless="0"'))
    assert "use either 'if' or 'unless', not both" in error(tmp_path, both)


def test_params_follow_the_parameter_server_last_one_wins(tmp_path):
    # Seed 004: the group's talker_str is written after the include, and wins.
    write_ros1(
        tmp_path,
        "talker.launch",
        '<param name="talker_str" type="str" value="hello world"/>' + node1("talker"),
    )
    xml = ros1(
        '<group if="true"><include file="talker.launch"/>'
        '<param name="talker_str" type="str" value="hello"/></group>'
    )
    assert params(plan(tmp_path, xml)[0]) == {"talker_str": "hello"}


def test_param_types_namespaces_and_private_names(tmp_path):
    xml = ros1(
        '<param name="top" value="1"/>\n<param name="/abs" type="double" value="1"/>\n'
        '<group ns="a"><param name="near" value="true"/><param name="top" value="2.5"/>\n'
        + node1("n", body='<param name="~mine" type="yaml" value="[1, 2]"/>'
                          '<param name="deep/x" value="text"/>')
        + '</group>\n<param name="a/n/late" type="str" value="7"/>\n' + node1("root")
    )  # fmt: skip
    in_group, at_root = plan(tmp_path, xml)
    assert params(in_group) == {
        "top": 2.5, "abs": 1.0, "near": True, "mine": [1, 2], "deep.x": "text", "late": "7",
    }  # fmt: skip
    assert params(at_root) == {"top": 1, "abs": 1.0}
    bad = ros1('<param name="x" type="int" value="seven"/>')
    assert "param 'x': 'seven' is not an int" in error(tmp_path, bad)


def test_rosparam_loads_yaml_from_a_file_or_inline(tmp_path):
    (tmp_path / "params.yaml").write_text("calculation_method: 2\nnested: {a: 1}\n")
    xml = ros1(
        node1("n", body='<rosparam file="$(dirname)/params.yaml"/>'
                        '<rosparam param="inline">{b: x}</rosparam>')
    )  # fmt: skip
    assert params(plan(tmp_path, xml)[0]) == {
        "calculation_method": 2,
        "nested.a": 1,
        "inline.b": "x",
    }
    bad = ros1('<rosparam command="forget" file="x"/>')
    assert "<rosparam command='forget'>: use load, delete or dump" in error(tmp_path, bad)


def test_group_remaps_and_env_apply_to_later_nodes_in_scope_only(tmp_path):
    xml = ros1(
        node1("before")
        + '<group><remap from="a" to="b"/><env name="X" value="1"/>' + node1("inside") + "</group>"
        + node1("after")
    )  # fmt: skip
    before, inside, after = plan(tmp_path, xml)
    assert inside.remaps == [("a", "b")] and inside.env == {"X": "1"}
    assert before.remaps == after.remaps == [] and before.env == after.env == {}


def test_include_is_scoped_and_takes_args_ns_and_pass_all_args(tmp_path):
    inner = '<arg name="who"/><arg name="private" default="p"/>' + node1("$(arg who)")
    write_ros1(tmp_path, "inner.launch", inner)
    xml = ros1(
        '<arg name="who" default="outer"/>\n'
        '<include file="$(dirname)/inner.launch" ns="sub"><arg name="who" value="in"/></include>\n'
        '<include file="inner.launch" pass_all_args="true"/>\n'
        + node1("$(arg who)x")
    )  # fmt: skip
    assert [s.node for s in plan(tmp_path, xml)] == ["/sub/in", "/outer", "/outerx"]
    leak = ros1('<include file="inner.launch"><arg name="who" value="in"/></include>'
                + node1("$(arg private)"))  # fmt: skip
    assert "argument 'private' is not declared here" in error(tmp_path, leak)
    extra = ros1('<include file="inner.launch"><arg name="who" value="a"/>'
                 '<arg name="what" value="b"/></include>')  # fmt: skip
    assert "what is declared in inner.launch (declared: private, who)" in error(tmp_path, extra)


def test_include_loops_and_missing_files_are_errors(tmp_path):
    write_ros1(tmp_path, "loop.launch", '<include file="test.launch"/>')
    assert "include each other in a loop" in error(tmp_path, ros1('<include file="loop.launch"/>'))
    assert "included file" in error(tmp_path, ros1('<include file="nothing.launch"/>'))


def test_substitutions_find_env_optenv_anon_dirname(tmp_path, monkeypatch):
    monkeypatch.setenv("LAUNCH_TEST_NAME", "from_env")
    monkeypatch.delenv("LAUNCH_TEST_UNSET", raising=False)
    xml = ros1(
        node1("$(env LAUNCH_TEST_NAME)", extra='args="$(find ros_tutorials_topic) $(dirname)"')
        + node1("$(optenv LAUNCH_TEST_UNSET fallback)")
        + node1("$(anon pub)") + node1("x", type_="subscriber", extra='args="$(anon pub)"')
    )  # fmt: skip
    first, second, third, fourth = plan(tmp_path, xml)
    assert first.label == "from_env" and second.label == "fallback"
    assert first.command[4:6] == [str(TOPIC_LAUNCH.parent), str(tmp_path)]
    assert third.label.startswith("pub_") and fourth.command[4] == third.label  # same anon name
    unset = ros1(node1("$(env LAUNCH_TEST_UNSET)"))
    assert "environment variable LAUNCH_TEST_UNSET is not set" in error(tmp_path, unset)
    unknown = ros1(node1("$(nope x)"))
    assert "unknown substitution $(nope); known here: $(arg), $(find)" in error(tmp_path, unknown)
    assert "unknown package 'nope'" in error(tmp_path, ros1(node1("$(find nope)")))


def test_eval_runs_code_only_when_allowed(tmp_path):
    # Values, argument names, operators and a few pure functions need no code ...
    xml = ros1('<arg name="n" default="2"/>' + node1("$(eval 'n' + str(int(n) * 21))"))
    assert plan(tmp_path, xml)[0].label == "n42"
    # ... a method call does: Python's eval, only with --allow-code.
    xml = ros1('<arg name="n" default="2"/>\n' + node1("$(eval 'n'.upper() + str(n))"))
    assert (
        "test.launch:3: $(eval 'n'.upper() + str(n)) runs code written in the launch file "
        "('n'.upper()); pass --allow-code to allow it"
    ) in error(tmp_path, xml)
    assert plan(tmp_path, xml, allow_code=True)[0].label == "N2"


def test_unknown_tags_and_attributes_name_the_place_and_the_allowed_set(tmp_path):
    message = error(tmp_path, ros1('<nodes name="m"/>'))
    assert message.startswith(f"{tmp_path / 'test.launch'}:2: unknown tag <nodes> in <launch>")
    assert "allowed: <arg>, <env>, <group>, <include>, <node>, <param>" in message
    message = error(tmp_path, ros1('<machine name="m"/>'))
    assert message.endswith(":2: <machine> is not supported: remote machines are roslaunch's "
                            "(ROS 2 nodes find each other by discovery: start the node on that "
                            "machine)")  # fmt: skip
    message = error(tmp_path, ros1(node1(extra='machine="m"')))
    assert ":2: unknown attribute 'machine' on <node>; allowed: args, clear_params, if" in message
    assert "unknown tag <group> in <node>" in error(tmp_path, ros1(node1(body="<group/>")))


def test_ros1_arg_choices_are_checked_not_a_traceback(tmp_path):
    # <choice> inside <arg> once raised a KeyError in the ROS 1 format; both formats take it.
    xml = ros1('<arg name="who" default="pub"><choice value="pub"/><choice value="b"/></arg>')
    assert plan(tmp_path, xml) == []
    assert "argument 'who' is 'x'; choose one of ['pub', 'b']" in error(tmp_path, xml, who="x")
    message = error(tmp_path, ros1('<arg name="who" default="a"><choice colour="red"/></arg>'))
    assert "unknown attribute 'colour' on <choice>; allowed: if, unless, value" in message


def test_node_errors_before_anything_starts(tmp_path):
    assert "a second node named /pub (the first is at" in error(tmp_path, ros1(node1() + node1()))
    both = ros1(node1(extra='respawn="true" required="true"'))
    assert "cannot be both respawn and required" in error(tmp_path, both)
    assert "output='loud'" in error(tmp_path, ros1(node1(extra='output="loud"')))
    assert "invalid node name 'a b'" in error(tmp_path, ros1(node1("a b")))
    assert "invalid namespace '1x'" in error(tmp_path, ros1(f'<group ns="1x">{node1()}</group>'))
    assert "'respawn_delay' must be a non-negative number" in error(
        tmp_path, ros1(node1(extra='respawn_delay="-1"'))
    )
    assert "program 'no-such-prefix' not found" in error(
        tmp_path, ros1(node1(extra='launch-prefix="no-such-prefix -x"'))
    )


def test_node_options_respawn_required_output_and_launch_prefix(tmp_path):
    xml = ros1(
        node1("a", extra='respawn="true" respawn_delay="2" output="screen" launch-prefix="env"')
        + node1("b", extra='required="true"')
    )
    a, b = plan(tmp_path, xml)
    assert a.respawn and a.respawn_delay == 2.0 and a.output == "screen" and not a.required
    assert a.command[0] == "env" and a.command[1] == sys.executable
    assert b.required and not b.respawn and b.output == "log"


# -- ROS 2 format ----------------------------------------------------------------------------


def node2(name: str = "pub", exec_: str = "publisher", extra: str = "", body: str = "") -> str:
    return f'<node pkg="ros_tutorials_topic" exec="{exec_}" name="{name}" {extra}>{body}</node>'


def test_ros2_args_let_var_choices_and_show_args(tmp_path):
    xml = (
        '<launch>\n<arg name="who" default="pub" description="the node name">'
        '<choice value="pub"/><choice value="other"/></arg>\n'
        '<let name="suffix" value="$(var who)_2"/>\n' + node2("$(var suffix)") + "</launch>"
    )
    assert plan(tmp_path, xml, "t.launch.xml")[0].label == "pub_2"
    assert plan(tmp_path, xml, "t.launch.xml", who="other")[0].label == "other_2"
    assert "choose one of ['pub', 'other']" in error(tmp_path, xml, "t.launch.xml", who="x")
    (info,) = describe_args(tmp_path / "t.launch.xml")
    assert (info.name, info.default, info.description, info.choices, info.fixed) == (
        "who", "pub", "the node name", ["pub", "other"], False,
    )  # fmt: skip


def test_ros2_namespaces_scoped_groups_and_settings(tmp_path):
    xml = (
        "<launch>\n"
        '<set_env name="A" value="1"/><set_remap from="x" to="y"/>'
        '<set_parameter name="shared" value="3"/>\n'
        '<group><push_ros_namespace namespace="g"/><unset_env name="A"/>'
        + node2("in_group", extra='namespace="sub"')
        + "</group>\n"
        '<group scoped="false"><push-ros-namespace namespace="leaks"/></group>\n'
        + node2("after", extra='ros_args="--log-level debug"',
                body='<param name="rate" value="2.5"/><remap from="a" to="b"/>'
                     '<env name="B" value="2"/><param from="p.yaml"/>')
        + "</launch>"
    )  # fmt: skip
    (tmp_path / "p.yaml").write_text("/**:\n  ros__parameters:\n    rate: 1.0\n")
    in_group, after = plan(tmp_path, xml, "t.launch.xml")
    assert in_group.node == "/g/sub/in_group" and in_group.env == {"A": None}
    assert after.node == "/leaks/after" and after.env == {"A": "1", "B": "2"}
    assert after.remaps == [("x", "y"), ("a", "b")]
    assert params(after) == {"shared": 3, "rate": 2.5}
    tail = after.command[after.command.index("--params-file") :]
    assert tail == ["--params-file", str(tmp_path / "p.yaml"), "--log-level", "debug"]


def test_ros2_group_forwarding_and_keep_as_in_ros2_launch(tmp_path):
    # GroupAction(forwarding=False): the group starts with only its <keep>s' configurations.
    xml = (
        '<launch>\n<let name="who" value="outer"/><let name="other" value="x"/>\n'
        '<group scoped="true" forwarding="false">\n'
        '<keep name="who" value="$(var who)_kept"/>\n' + node2("$(var who)") + "\n"
        "$BODY</group>\n" + node2("$(var who)_after") + "</launch>"
    )
    inside, after = plan(tmp_path, xml.replace("$BODY", ""), "t.launch.xml")
    assert (inside.label, after.label) == ("outer_kept", "outer_after")
    message = error(tmp_path, xml.replace("$BODY", node2("$(var other)")), "t.launch.xml")
    assert ":6: argument 'other' is not declared here (declared: who)" in message
    forwarded = xml.replace('forwarding="false"', 'forwarding="true"')
    inside, _, after = plan(tmp_path, forwarded.replace("$BODY", node2("$(var other)")),
                            "t.launch.xml")  # fmt: skip
    assert (inside.label, after.label) == ("outer_kept", "outer_after")
    yaml_text = (
        "launch:\n- let: {name: who, value: outer}\n"
        "- group:\n    forwarding: false\n    keep: [{name: who, value: $(var who)_y}]\n"
        "    children:\n    - node: {pkg: ros_tutorials_topic, exec: publisher, name: $(var who)}\n"
    )
    assert plan(tmp_path, yaml_text, "t.launch.yaml")[0].label == "outer_y"
    bad = xml.replace('<keep name="who"', '<keep colour="red" name="who"').replace("$BODY", "")
    message = error(tmp_path, bad, "t.launch.xml")
    assert ":4: unknown attribute 'colour' on <keep>; allowed: if, name, unless, value" in message


def test_ros2_include_is_scoped(tmp_path):
    (tmp_path / "inner.launch.xml").write_text(
        '<launch><arg name="who"/><set_env name="LEAK" value="1"/>'
        + node2("$(var who)")
        + "</launch>"
    )
    xml = (
        '<launch><include file="inner.launch.xml"><arg name="who" value="in"/></include>'
        + node2("out")
        + "</launch>"
    )
    inner, outer = plan(tmp_path, xml, "t.launch.xml")
    assert inner.env == {"LEAK": "1"} and outer.env == {}


def test_ros2_executable_log_and_process_options(tmp_path):
    xml = (
        '<launch><log message="hello $(var x)"/><arg name="x" default="1"/>'
        '<executable cmd="sleep 5" name="nap" output="both" respawn="true" '
        'respawn_max_retries="3" sigterm_timeout="1" sigkill_timeout="2"/>'
        + node2(extra='on_exit="shutdown"')
        + "</launch>"
    )
    message = error(tmp_path, xml, "t.launch.xml")
    assert "argument 'x' is not declared here" in message  # used before it is declared
    xml = xml.replace("$(var x)", "world")
    path = tmp_path / "t.launch.xml"
    path.write_text(xml)
    launch = resolve(path, {})
    nap, pub = make_plan(launch)
    assert launch.messages == ["hello world"]
    assert nap.command == ["sleep", "5"] and nap.label == "nap" and nap.node is None
    assert (nap.respawn, nap.respawn_max_retries, nap.sigterm_timeout, nap.sigkill_timeout) == (
        True, 3, 1.0, 2.0,
    )  # fmt: skip
    assert pub.required and pub.sigterm_timeout == 5.0
    bad = '<launch><executable cmd="sleep 1" on_exit="restart"/></launch>'
    assert "on_exit='restart' is not supported" in error(tmp_path, bad, "t.launch.xml")


def test_ros2_logic_and_env_substitutions(tmp_path, monkeypatch):
    monkeypatch.delenv("LAUNCH_TEST_UNSET", raising=False)
    xml = (
        '<launch><arg name="a" default="true"/>'
        + node2("n1", extra='if="$(and $(var a) $(not false))"')
        + node2("n2", extra='if="$(or false $(equals $(var a) false))"')
        + node2("$(env LAUNCH_TEST_UNSET fallback)")
        + node2("n3", extra="args=\"$(find-pkg-prefix ros_tutorials_topic) 'two words'\"")
        + "</launch>"
    )
    n1, fallback, n3 = plan(tmp_path, xml, "t.launch.xml")
    assert (n1.label, fallback.label) == ("n1", "fallback")
    assert n3.command[4:6] == [sys.prefix, "two words"]  # the install prefix, as ament's


def test_ros2_command_substitution_is_opt_in(tmp_path):
    xml = "<launch>" + node2("$(command echo -n from_command)") + "</launch>"
    assert "$(command) runs a program named in the launch file; pass --allow-code" in error(
        tmp_path, xml, "t.launch.xml"
    )
    assert plan(tmp_path, xml, "t.launch.xml", allow_code=True)[0].label == "from_command"
    xml = "<launch>" + node2("$(eval 'chr(110) + str(2 ** 3)')") + "</launch>"
    assert plan(tmp_path, xml, "t.launch.xml", allow_code=True)[0].label == "n8"


def test_ros2_unknown_tags_and_attributes(tmp_path):
    message = error(tmp_path, "<launch>\n<bogus/></launch>", "t.launch.xml")
    assert (
        ":2: unknown tag <bogus> in <launch> (ROS 2 format); allowed: <append_env>, <arg>"
        in message
    )
    message = error(tmp_path, "<launch>" + node2(extra='type="x"') + "</launch>", "t.launch.xml")
    assert "mixes ROS 1 syntax" in message
    message = error(tmp_path, "<launch>" + node2(extra='colour="red"') + "</launch>", "t.xml")
    allowed = "allowed: args, emulate_tty, exec, exec_name, if"
    assert f"unknown attribute 'colour' on <node>; {allowed}" in message


@pytest.mark.skipif(
    importlib.util.find_spec("ros_tutorials_parameter") is None
    or not packages.executables("ros_tutorials_parameter"),
    reason="ros_tutorials_parameter (the parameter lesson) is not merged into this branch yet",
)
def test_parameter_lesson_launch_files_set_their_parameters():
    folder = packages.package_dirs()["ros_tutorials_parameter"] / "launch"
    for name in (
        "service_server_with_parameter.launch",
        "service_server_with_parameter.launch.xml",
    ):
        (spec,) = make_plan(resolve(folder / name, {"calculation_method": "3"}))
        assert params(spec) == {"calculation_method": 3}
    talker = make_plan(resolve(folder / "combine.launch", {"hello": "false"}))
    assert [params(spec) for spec in talker] == [{"talker_str": "goodbye"}] * 2
