"""The launcher beside the real launchers' own tests, without processes: roslaunch's
(ros/ros_comm tools/roslaunch/test/xml with test_xmlloader.py) and launch_xml's and
launch_ros's front-end tests (ros2/launch, ros2/launch_ros, branch jazzy), their cases
written here in this project's words: which format a file is read in, remaps, private
parameters, arguments, $(eval), includes."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import fails, ok, run

from launch_foundation.parse import parse_file
from launcher import CodeRefused, LaunchError
from launcher.loading import resolve
from launcher.plan import make_plan
from launcher.scope import Options
from launcher.tags import detect

PKG = 'pkg="ros_tutorials_topic"'


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text)
    return path


def planned(path: Path, **args: str):
    launch = resolve(path, args, Options())
    return launch, {spec.node: spec for spec in make_plan(launch)}


def raised(path: Path, **args: str) -> str:
    with pytest.raises(LaunchError) as caught:
        planned(path, **args)
    return str(caught.value)


def ros1_node(name: str, body: str = "", extra: str = "") -> str:
    return f'<node {PKG} type="topic_publisher" name="{name}" {extra}>{body}</node>'


# -- which format: every sign in the file, not only its tags ---------------------------------

FORMATS = [
    # (what the file uses, its text inside <launch>, its name, the format)
    ("<arg value> (a ROS 1 constant)", '<arg name="a" value="1"/>', "t.xml", "ros1"),
    ("<arg doc>", '<arg name="a" default="1" doc="d"/>', "t.xml", "ros1"),
    ("$(arg) in a shared tag", '<arg name="a" default="x"/><group/>'
     '<include file="$(arg a)"/>', "t.xml", "ros1"),
    ("$(find)", '<include file="$(find p)/x.launch"/>', "t.xml", "ros1"),
    ("<param> outside a <node>", '<param name="p" value="1"/>', "t.xml", "ros1"),
    ("<remap> outside a <node>", '<remap from="a" to="b"/>', "t.xml", "ros1"),
    ("<env> outside a <node>", '<env name="A" value="b"/>', "t.xml", "ros1"),
    ("<include pass_all_args>", '<include file="x.xml" pass_all_args="true"/>', "t.xml", "ros1"),
    ("<arg> in <include> is shared", '<include file="x"><arg name="a" value="1"/></include>',
     "t.xml", "ros2"),
    ("<arg description>", '<arg name="a" default="1" description="d"/>', "t.launch", "ros2"),
    ("$(var)", '<arg name="a" default="1"/><include file="$(var a)"/>', "t.launch", "ros2"),
    ("<group scoped>", '<group scoped="false"/>', "t.launch", "ros2"),
    ("nothing either format alone has: *.launch", '<arg name="a" default="1"/>', "t.launch",
     "ros1"),
    ("nothing either format alone has: *.xml", '<arg name="a" default="1"/>', "t.xml", "ros2"),
]  # fmt: skip


@pytest.mark.parametrize(("uses", "body", "name", "fmt"), FORMATS, ids=[f[0] for f in FORMATS])
def test_the_format_comes_from_every_sign_in_the_file(tmp_path, uses, body, name, fmt):
    # roslaunch's own test files are *.xml that use tags ROS 2 has too (24 of them failed)
    root = parse_file(write(tmp_path, name, f"<launch>{body}</launch>"))
    assert detect(root)[0] == fmt


def test_an_error_from_a_format_guessed_by_name_says_so(tmp_path):
    path = write(tmp_path, "t.xml", '<launch><arg name="a" default="1" doc2="x"/></launch>')
    assert raised(path).endswith(
        "(read as ROS 2 launch XML: nothing in it is only ROS 1 or only ROS 2, and its name "
        "is not *.launch)"
    )


# -- roslaunch: remaps, private parameters, $(eval) ------------------------------------------


def test_a_later_remap_of_the_same_name_replaces_the_earlier(tmp_path):
    # roslaunch's test-remap-valid.xml: remaps are read in order and scoped
    path = write(
        tmp_path,
        "t.xml",
        f"""<launch>
<remap from="foo" to="bar"/>
{ros1_node("n1")}
<group ns="ns1"><remap from="foo" to="baz"/>{ros1_node("n2")}</group>
{ros1_node("n3")}
<remap from="foo" to="far"/>
{ros1_node("n4")}
{ros1_node("n5", '<remap from="foo" to="fad"/><remap from="a" to="b"/>')}
<remap from="old1" to="new1"/><remap from="old2" to="new2"/>
{ros1_node("n6")}
</launch>""",
    )
    nodes = planned(path)[1]
    assert nodes["/n1"].remaps == [("foo", "bar")]
    assert nodes["/ns1/n2"].remaps == [("foo", "baz")]
    assert nodes["/n3"].remaps == [("foo", "bar")]
    assert nodes["/n4"].remaps == [("foo", "far")]  # not foo:=bar first, which rcl would apply
    assert nodes["/n5"].remaps == [("foo", "fad"), ("a", "b")]
    assert nodes["/n6"].remaps == [("foo", "far"), ("old1", "new1"), ("old2", "new2")]


def test_a_private_param_outside_a_node_goes_to_the_nodes_after_it_in_its_scope(tmp_path):
    # roslaunch's test-local-param-group.xml
    path = write(
        tmp_path,
        "t.xml",
        f"""<launch>
{ros1_node("node0")}
<group ns="group1">
  {ros1_node("g1node0")}
  <param name="~gparam1" value="val1"/>
  {ros1_node("g1node1")}
  <param name="~gparam2" value="val1"/>
  {ros1_node("g1node2", '<param name="~gparam2" value="own"/>')}
</group>
<param name="~param1" value="val1"/>
{ros1_node("node1")}
</launch>""",
    )
    launch, nodes = planned(path)
    assert {name: dict(spec.params) for name, spec in nodes.items()} == {
        "/node0": {},
        "/group1/g1node0": {},
        "/group1/g1node1": {"gparam1": "val1"},
        "/group1/g1node2": {"gparam1": "val1", "gparam2": "own"},  # its own <param> wins
        "/node1": {"param1": "val1"},
    }
    assert launch.warnings == []
    late = write(tmp_path, "late.xml", f'<launch>{ros1_node("n")}<param name="~p" value="1"/>'
                 "</launch>")  # fmt: skip
    assert resolve(late, {}, Options()).warnings == [
        f"{late}:1: param '~p' is given to no node: no <node> follows it in its scope"
    ]


IF_UNLESS = [
    # roslaunch's test-if-unless.xml: $(eval) sees arguments typed as roslaunch types them
    ("1 == 1", True),
    ("arg('true_lower') and (40+2) == 42", True),
    ("false_lower or (40-2) != 38", False),
    ("arg('false_upper') or 1 < 1", False),
    ("true_upper and 1 >= 1", True),
    ("arg('true_upper') == True", True),
    ("false_upper != False", False),
    ("arg('false_lower') or false_upper or arg('false_upper') != False", False),
    ("number + 1 == 43 and ratio * 2 == 1.0 and name == 'robot'", True),
    ("not false_lower and true", True),
    ("sqrt(number - 33) == 3 and pi > 3", True),
]


@pytest.mark.parametrize(("expression", "value"), IF_UNLESS, ids=[e[0] for e in IF_UNLESS])
def test_ros1_eval_sees_arguments_typed(tmp_path, expression, value):
    escaped = expression.replace("<", "&lt;").replace(">", "&gt;")
    path = write(
        tmp_path,
        "t.launch",
        f"""<launch>
<arg name="true_lower" value="true"/><arg name="true_upper" value="True"/>
<arg name="false_lower" value="false"/><arg name="false_upper" value="False"/>
<arg name="number" value="42"/><arg name="ratio" value="0.5"/><arg name="name" value="robot"/>
{ros1_node("n", extra=f'if="$(eval {escaped})"')}
</launch>""",
    )
    assert bool(planned(path)[1]) is value


def test_eval_without_code_is_bounded_and_code_needs_allow_code(tmp_path):
    def node(expression: str) -> Path:
        return write(tmp_path, "t.launch", f'<launch>{ros1_node(f"$(eval {expression})")}'
                     "</launch>")  # fmt: skip

    assert "failed: an integer of more than 4096 bits" in raised(node("9 ** 9 ** 9"))
    assert "failed: a value longer than 1048576 characters" in raised(node("'x' * 10 ** 7"))
    assert "failed: name 'nothing' is not defined" in raised(node("nothing + 1"))
    assert "'__' is not allowed in $(eval)" in raised(node("().__class__"))  # as roslaunch
    with pytest.raises(CodeRefused):
        planned(node("[n for n in 'ab'][0]"))


# -- roslaunch: arguments and pass_all_args --------------------------------------------------

INCLUDED = """<launch>
  <arg name="required"/><arg name="if_test"/><arg name="include_arg"/>
  <arg name="optional" default="not_set"/>
  <arg name="grounded" value="set"/>
  <group ns="include_test">
    <node pkg="ros_tutorials_topic" type="topic_publisher" name="n">
      <param name="p1" value="$(arg required)"/><param name="p2" value="$(arg optional)"/>
      <param name="p3" value="$(arg grounded)"/><param name="p4" value="$(arg include_arg)"/>
    </node>
  </group>
</launch>"""


def test_pass_all_args_as_roslaunch_tests_it(tmp_path):
    # roslaunch's test-arg-all.xml, including test-arg-include.xml four ways
    write(tmp_path, "inc.xml", INCLUDED)
    path = write(tmp_path, "t.xml", """<launch>
  <arg name="required"/><arg name="optional" default="not_set"/>
  <arg name="grounded" value="parent"/><arg name="include_arg" value="dontcare"/>
  <arg name="if_test" value="dontcare"/>
  <include ns="notall" file="inc.xml">
    <arg name="required" value="$(arg required)"/>
    <arg name="include_arg" value="$(arg include_arg)"/><arg name="if_test" value="$(arg if_test)"/>
  </include>
  <include ns="notall_optional" file="inc.xml">
    <arg name="required" value="$(arg required)"/><arg name="optional" value="$(arg optional)"/>
    <arg name="include_arg" value="$(arg include_arg)"/><arg name="if_test" value="$(arg if_test)"/>
  </include>
  <include ns="all" file="inc.xml" pass_all_args="true"/>
  <include ns="all_override" file="inc.xml" pass_all_args="true">
    <arg name="required" value="override"/>
  </include>
</launch>""")  # fmt: skip
    for optional in ("not_set", "test_arg2"):
        args = {"required": "test_arg"} | ({"optional": optional} if optional != "not_set" else {})
        nodes = planned(path, **args)[1]
        p = {name.split("/")[1]: dict(spec.params) for name, spec in nodes.items()}
        assert p["notall"] == {"p1": "test_arg", "p2": "not_set", "p3": "set", "p4": "dontcare"}
        assert p["notall_optional"]["p2"] == optional
        # the child's fixed grounded:=set wins over the parent's grounded passed by pass_all
        assert p["all"] == {"p1": "test_arg", "p2": optional, "p3": "set", "p4": "dontcare"}
        assert p["all_override"] == {**p["all"], "p1": "override"}


def test_pass_all_args_lets_the_child_use_arguments_it_does_not_declare(tmp_path):
    # roslaunch's test-dirname.xml: included.xml reads $(arg base) without declaring it
    (tmp_path / "sub").mkdir()
    write(tmp_path, "sub/included.xml", f"""<launch><arg name="baz"/>
{ros1_node("n", '<param name="base" value="$(arg base)"/><param name="baz" value="$(arg baz)"/>'
           '<param name="bar" value="$(dirname)/baz"/>')}</launch>""")  # fmt: skip
    path = write(
        tmp_path,
        "t.xml",
        """<launch><arg name="base" value="$(dirname)"/>
<include file="$(dirname)/sub/included.xml" pass_all_args="True">
  <arg name="baz" value="$(dirname)/baz"/>
</include></launch>""",
    )
    (node,) = planned(path)[1].values()
    assert dict(node.params) == {"base": str(tmp_path), "baz": f"{tmp_path}/baz",
                                 "bar": f"{tmp_path}/sub/baz"}  # fmt: skip


def test_a_fixed_argument_cannot_be_set_except_by_pass_all_args(tmp_path):
    # roslaunch's test-arg-invalid-include.xml and test-arg-valid-include.xml
    write(tmp_path, "inc.xml", f'<launch><arg name="grounded" value="set"/>{ros1_node("n")}'
          "</launch>")  # fmt: skip
    explicit = write(tmp_path, "bad.xml", '<launch><include file="inc.xml">'
                     '<arg name="grounded" value="not_set"/></include></launch>')  # fmt: skip
    assert "argument 'grounded' has a fixed value and cannot be set" in raised(explicit)
    by_all = write(tmp_path, "good.xml", '<launch><arg name="grounded" value="not_set"/>'
                   '<arg name="unused" value="x"/>'
                   '<include file="inc.xml" pass_all_args="true"/></launch>')  # fmt: skip
    assert list(planned(by_all)[1]) == ["/n"]


def test_an_argument_without_a_value_is_an_error_only_where_it_is_used(tmp_path):
    # roslaunch's test-arg.xml declares if_test and required; only their use fails
    path = write(tmp_path, "t.launch", f'<launch>\n<arg name="unused"/>\n<arg name="who"/>\n'
                 f'{ros1_node("$(arg who)")}\n</launch>')  # fmt: skip
    assert list(planned(path, who="n")[1]) == ["/n"]
    assert raised(path).endswith(
        "t.launch:4: argument 'who' is required (declared at line 3 without a value): "
        "pass who:=<value>"
    )


# -- ROS 2: includes are not scoped, as in ros2 launch -----------------------------------------


def ros2_file(folder: Path, name: str, body: str) -> Path:
    return write(folder, name, f"<launch>\n{body}\n</launch>")


def test_a_ros2_include_sees_the_includers_configurations_and_says_so(tmp_path):
    # A real pattern: an included file reads $(var robot) that its includer declared.
    child = ros2_file(tmp_path, "child.launch.xml", '<arg name="rate" default="1"/>\n'
                      '<executable cmd="echo $(var robot) $(var rate)"/>')  # fmt: skip
    parent = ros2_file(
        tmp_path,
        "parent.launch.xml",
        '<arg name="robot" default="r2"/>\n'
        '<arg name="rate" default="5"/>\n<include file="child.launch.xml"/>',
    )
    launch = resolve(parent, {}, Options())
    assert make_plan(launch)[0].command == ["echo", "r2", "5"]  # not the child's default 1
    assert launch.warnings == [
        f"{child}:2: argument 'rate' is '5', the value of the file including this one (not "
        "passed to it), not its default; ros2 launch lets it in (its includes are not scoped)",
        f"{child}:3: 'robot' ('r2') is not passed to this file but comes from the file "
        "including it; ros2 launch lets it in (its includes are not scoped)",
    ]


def test_what_a_ros2_include_sets_stays_set_after_it(tmp_path):
    write(tmp_path, "child.launch.yaml", "launch:\n- let: {name: mode, value: fast}\n")
    parent = ros2_file(tmp_path, "parent.launch.xml", '<include file="child.launch.yaml">'
                       '<arg name="extra" value="1"/></include>\n'
                       '<executable cmd="echo $(var mode) $(var extra)"/>')  # fmt: skip
    launch = resolve(parent, {}, Options())
    assert make_plan(launch)[0].command == ["echo", "fast", "1"]
    assert launch.warnings == [
        f"{parent}:2: child.launch.yaml declares no argument 'extra' and does not read it "
        "(declared: none)",
        f"{parent}:3: 'mode' ('fast') was set by child.launch.yaml (included at line 2); "
        "ros2 launch lets it out (its includes are not scoped)",
    ]


def test_ros1_includes_stay_scoped_as_in_roslaunch(tmp_path):
    write(tmp_path, "child.launch", f"<launch>{ros1_node('$(arg robot)')}</launch>")
    parent = write(tmp_path, "parent.launch", '<launch><arg name="robot" default="r"/>'
                   '<include file="child.launch"/></launch>')  # fmt: skip
    assert "argument 'robot' is not declared here (declared: none)" in raised(parent)


# -- the command line ----------------------------------------------------------------------


def test_a_deprecated_launch_file_prints_its_message(tmp_path):
    path = write(
        tmp_path,
        "old.launch.xml",
        '<launch deprecated="use new.launch.xml"><executable cmd="true"/></launch>',
    )
    result = run("ros2", "launch", str(path), "--print")
    assert "command: true" in result.stdout
    assert result.stderr == f"warning: launch file [{path}] is deprecated: use new.launch.xml\n"


def test_code_in_a_launch_file_is_refused_with_the_command_that_allows_it(tmp_path):
    # Real launchers evaluate $(eval) with Python; here only what needs no code runs by itself
    # (the Using-Substitutions YAML file does), and the rest asks for --allow-code.
    path = write(
        tmp_path,
        "t.launch.xml",
        """<launch><executable cmd="echo $(eval &quot;'a'.upper()&quot;)"/></launch>""",
    )
    line = fails("ros2", "launch", str(path), "--print")
    assert line == (
        f"error: {path}:1: $(eval 'a'.upper()) runs code written in the launch file "
        f"('a'.upper()); to allow it, run: ros2 launch {path} --print --allow-code"
    )
    assert "command: echo A" in ok("ros2", "launch", str(path), "--print", "--allow-code")


# -- launch_ros: a node's parameters in XML and YAML (test_node_frontend.py) ------------------

NODE_XML = """<launch>
  <let name="a_list" value="[2, 5, 8]"/><let name="my_value" value="100"/>
  <node pkg="ros_tutorials_topic" exec="talker" name="my_talker" namespace="my_ns"
        exec_name="my_talker_process" ros_args="--log-level info">
    <param name="param1" value="ads"/>
    <param name="param_group1">
      <param name="param_group2"><param name="param2" value="2"/></param>
      <param name="param3" value="2, 5, 8" value-sep=", "/>
      <param name="param4" value="$(var a_list)"/>
      <param name="param6" value="2., 5., 8." value-sep=", "/>
      <param name="param7" value="'2', '5', '8'" value-sep=", "/>
      <param name="param8" value-sep=", "
             value="&quot;'2'&quot;, &quot;'5'&quot;, &quot;'8'&quot;"/>
      <param name="param12" value="''"/>
      <param name="param13" value="$(var my_value)" type="str"/>
      <param name="param14" value="'2', '5', '8'" value-sep=", " type="list_of_str"/>
      <param name="param15" value="2, 5, 8" value-sep=", " type="list_of_str"/>
    </param>
  </node>
</launch>"""
NODE_YAML = """launch:
- let: {name: a_list, value: '[2, 5, 8]'}
- let: {name: my_value, value: '100'}
- node:
    pkg: ros_tutorials_topic
    exec: talker
    name: my_talker
    namespace: my_ns
    exec_name: my_talker_process
    ros_args: --log-level info
    param:
    - {name: param1, value: ads}
    - name: param_group1
      param:
      - name: param_group2
        param:
        - {name: param2, value: 2}
      - {name: param3, value: [2, 5, 8]}
      - {name: param4, value: $(var a_list)}
      - {name: param6, value: [2., 5., 8.]}
      - {name: param7, value: ['2', '5', '8']}
      - {name: param8, value: ["'2'", "'5'", "'8'"]}
      - {name: param12, value: ''}
      - {name: param13, value: $(var my_value), type: str}
      - {name: param14, value: ["'2'", "'5'", "'8'"], type: list_of_str}
      - {name: param15, value: ['2', '5', '8'], type: list_of_str}
"""


@pytest.mark.parametrize(("name", "text"), [("t.launch.xml", NODE_XML), ("t.yaml", NODE_YAML)])
def test_node_parameters_as_launch_ros_types_them(tmp_path, name, text):
    _, nodes = planned(write(tmp_path, name, text))
    node = nodes["/my_ns/my_talker"]
    assert node.process_name == "my_talker_process"  # exec_name: the process, not the node
    assert node.command[-2:] == ["--log-level", "info"]
    group = "param_group1."
    assert dict(node.params) == {
        "param1": "ads",
        group + "param_group2.param2": 2,
        group + "param3": [2, 5, 8],
        group + "param4": [2, 5, 8],
        group + "param6": [2.0, 5.0, 8.0],
        group + "param7": ["2", "5", "8"],
        group + "param8": ["'2'", "'5'", "'8'"],
        group + "param12": "",
        group + "param13": "100",
        group + "param14": ["'2'", "'5'", "'8'"],
        group + "param15": ["2", "5", "8"],
    }


@pytest.mark.parametrize(
    ("param", "error"),
    [
        ('<param name="p" value="x" type="int"/>', "param 'p': 'x' is not int"),
        ('<param name="p" value="[1, 2]" type="list_of_str"/>', "is not a list of str"),
        ('<param name="p" value="1" type="double"/>', "unknown parameter type 'double'"),
        ('<param name="g" value="1"><param name="p" value="1"/></param>', "either a value or"),
    ],
)
def test_node_parameter_types_are_checked(tmp_path, param, error):
    text = f'<launch><node {PKG} exec="talker">{param}</node></launch>'
    assert error in raised(write(tmp_path, "t.launch.xml", text))


def test_a_python_file_and_the_xml_file_it_includes_share_configurations(tmp_path):
    child = ros2_file(tmp_path, "child.launch.xml", '<let name="mode" value="fast"/>\n'
                      '<executable cmd="echo $(var robot)"/>')  # fmt: skip
    parent = write(
        tmp_path,
        "parent.launch.py",
        """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r2'),
        IncludeLaunchDescription(AnyLaunchDescriptionSource('child.launch.xml')),
        ExecuteProcess(cmd=['echo', LaunchConfiguration('mode')]),
    ])
""",
    )
    launch = resolve(parent, {}, Options())
    assert [spec.command for spec in make_plan(launch)] == [["echo", "r2"], ["echo", "fast"]]
    assert launch.warnings == [
        f"{child}:3: 'robot' ('r2') is not passed to this file but comes from the file "
        "including it; ros2 launch lets it in (its includes are not scoped)"
    ]
