"""What learners hit following the seeds: each mistake is one clear line, before anything starts.

Every test runs the launcher's main() with --print (or resolves and plans only): no process
is started, and what is checked is what the user sees, the error line and the exit status.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_foundation.naming import remap_problem
from launcher.__main__ import main

NODE = '<node pkg="ros_tutorials_topic" type="topic_publisher" name="pub">{}</node>'


def launch(capsys, *words: str) -> tuple[int, list[str], str]:
    """main() with --print: its exit status, its stderr lines and its stdout."""
    status = main([*words, "--print"])
    out, err = capsys.readouterr()
    assert "Traceback" not in err
    return status, err.strip().splitlines(), out


def refused(capsys, *words: str) -> str:
    """The one error line of a launch that must be refused (nothing printed to stdout)."""
    status, lines, out = launch(capsys, *words)
    assert status == 1 and out == "", (status, lines, out)
    assert len(lines) == 1 and lines[0].startswith("error: "), lines
    return lines[0]


def ros1_file(tmp_path: Path, body: str, name: str = "test.launch") -> Path:
    path = tmp_path / name
    path.write_text(f"<launch>\n{body}\n</launch>\n")
    return path


# 1. name=value instead of name:=value


def test_an_argument_with_equals_says_arguments_are_name_colon_equals_value(capsys):
    line = refused(capsys, "union.launch", "use_server=false")
    assert "did you mean use_server:=false?" in line
    assert "name:=value" in line and "unknown package" not in line


# 2. an <include> passing an argument the included file does not declare


def test_an_undeclared_include_argument_names_the_including_file_and_line(capsys, tmp_path):
    ros1_file(tmp_path, '<arg name="topic" default="chatter"/>', "x.launch")
    path = ros1_file(
        tmp_path, '<include file="x.launch">\n  <arg name="topc" value="news"/>\n</include>'
    )
    line = refused(capsys, str(path))
    assert line.startswith(f"error: {path}:3: ")
    assert "no argument named topc is declared in x.launch (declared: topic)" in line


# 3. an argument declared twice in one ROS 1 file


def test_an_argument_declared_twice_is_refused_with_both_places(capsys, tmp_path):
    path = ros1_file(
        tmp_path, '<arg name="a" default="1"/>\n<group><arg name="a" value="2"/></group>'
    )
    line = refused(capsys, str(path))
    assert line == (
        f"error: {path}:3: argument 'a' is declared twice (first at line 2); "
        "roslaunch refuses that too"
    )


def test_sibling_groups_may_each_declare_an_argument(capsys, tmp_path):
    """roslaunch gives each group a copy of the names declared so far: a name declared in
    one group is not declared in the next, nor after the groups."""
    path = ros1_file(
        tmp_path,
        '<group ns="g"><arg name="x" default="1"/></group>\n'
        '<group ns="h"><arg name="x" default="2"/></group>\n'
        '<arg name="x" default="3"/>\n' + NODE.format('<param name="x" value="$(arg x)"/>'),
    )
    status, lines, out = launch(capsys, str(path))
    assert status == 0 and lines == [] and "param:   x = 3" in out


def test_an_argument_declared_under_exclusive_conditions_is_accepted(capsys, tmp_path):
    path = ros1_file(
        tmp_path,
        '<arg name="fast" default="true"/>\n'
        '<arg name="rate" default="10" if="$(arg fast)"/>\n'
        '<arg name="rate" default="1" unless="$(arg fast)"/>\n'
        + NODE.format('<param name="rate" value="$(arg rate)"/>'),
    )
    status, lines, out = launch(capsys, str(path))
    assert status == 0 and lines == [] and "param:   rate = 10" in out


# 4. remap names are checked as rcl checks them, before anything starts


@pytest.mark.parametrize(
    ("attrs", "bad"),
    [
        ('from="chat ter" to="x"', "from='chat ter'"),
        ('from="chatter" to="1x"', "to='1x'"),
        ('from="a//b" to="x"', "from='a//b'"),
        ('from="chatter" to="news/"', "to='news/'"),
        ('from="chatter" to="$(arg t)"', "to='a-b'"),  # the substitution's result is checked
        ('from="chatter" to="{node}/x"', "to='{node}/x'"),
    ],
)
def test_a_remap_that_is_not_a_ros_name_is_refused_at_its_line(capsys, tmp_path, attrs, bad):
    path = ros1_file(tmp_path, '<arg name="t" default="a-b"/>\n' + NODE.format(f"<remap {attrs}/>"))
    line = refused(capsys, str(path))
    assert line.startswith(f"error: {path}:3: remap {bad} is not a valid ROS name")


def test_a_remap_in_a_ros2_file_is_checked_too(capsys, tmp_path):
    path = tmp_path / "test.launch.xml"
    path.write_text(
        '<launch>\n<node pkg="ros_tutorials_topic" exec="publisher">\n'
        '  <remap from="chatter" to="~news"/>\n</node>\n</launch>\n'
    )
    line = refused(capsys, str(path))
    assert line.startswith(f"error: {path}:3: remap to='~news' is not a valid ROS name")


def test_private_and_absolute_remaps_pass_and_ros1_tilde_names_become_ros2_ones(capsys, tmp_path):
    remaps = '<remap from="~chatter" to="/news"/><remap from="rostopic://a" to="~/b_2"/>'
    path = ros1_file(tmp_path, NODE.format(remaps))
    status, lines, out = launch(capsys, str(path))
    assert status == 0 and lines == [], lines
    assert "remap:   ~/chatter -> /news\n    remap:   rostopic://a -> ~/b_2" in out


@pytest.mark.parametrize(
    "rule",
    ["a:=b", "/a/b:=c", "~/a:=b", "_a:=~/b", "rostopic://a:=b", "rosservice://a/b:=/c",
     "chat ter:=x", "~a:=b", "~:=b", "a:=~b", "1a:=b", "a:=1b", "a/:=b", "a//b:=c", "a:=b/",
     "a:={node}/x", "**:=b", "a*:=b", "a-b:=c", "a.b:=c", "a:=", ":=a", "/:=a", "a:=b~", "ä:=b"],
)  # fmt: skip
def test_the_remap_check_agrees_with_rcl(rule):
    """rcl itself parses each rule (no node, no DDS participant): both must agree."""
    rclpy = pytest.importorskip("rclpy")
    source, _, target = rule.partition(":=")
    context = rclpy.context.Context()
    try:
        rclpy.init(args=["--ros-args", "-r", rule], context=context)
    except Exception:
        rcl_accepts = False
    else:
        rcl_accepts = True
        rclpy.shutdown(context=context)
    ours = remap_problem(source, "from") is None and remap_problem(target, "to") is None
    assert ours == rcl_accepts


# 5. a <param type=...> whose value is not of that type


@pytest.mark.parametrize(
    ("kind", "value", "expected"),
    [
        ("int", "abc", "param 'x': 'abc' is not an int"),
        ("int", "1.5", "param 'x': '1.5' is not an int"),
        ("double", "fast", "param 'x': 'fast' is not a double"),
        ("bool", "yes please", "param 'x': 'yes please' is not a bool (true, false, 1 or 0)"),
    ],
)
def test_a_param_of_the_wrong_type_says_so_in_ros_terms(capsys, tmp_path, kind, value, expected):
    path = ros1_file(tmp_path, NODE.format(f'<param name="x" type="{kind}" value="{value}"/>'))
    assert refused(capsys, str(path)) == f"error: {path}:2: {expected}"


def test_a_yaml_param_that_is_not_yaml_names_the_yaml_error(capsys, tmp_path):
    path = ros1_file(tmp_path, NODE.format('<param name="x" type="yaml" value="{a: [1, 2"/>'))
    line = refused(capsys, str(path))
    assert line.startswith(f"error: {path}:2: ") and "YAML" in line and "bool" not in line


# 6. unknown attributes are listed as the file's format spells them


def test_unknown_attribute_lists_launch_prefix_as_ros1_spells_it(capsys, tmp_path):
    path = ros1_file(tmp_path, NODE.format("").replace("<node ", '<node launch-prefx="nice" '))
    line = refused(capsys, str(path))
    assert line.startswith(f"error: {path}:2: unknown attribute 'launch-prefx' on <node>")
    assert "launch-prefix" in line and "launch_prefix" not in line


# 7. a package without a file, a file in another package


def test_a_package_alone_says_it_is_a_package_and_lists_its_launch_files(capsys):
    line = refused(capsys, "ros_tutorials_topic")
    assert "ros_tutorials_topic is a package; name one of its launch files" in line
    assert "union.launch" in line and "multisim.launch" not in line


def test_a_file_of_another_package_says_where_it_is(capsys):
    line = refused(capsys, "ros_tutorials_service", "union.launch")
    assert "ros_tutorials_service has no launch file 'union.launch'" in line
    assert "union.launch is in ros_tutorials_topic: roslaunch ros_tutorials_topic union.launch" in (
        line.replace("python -m launcher", "roslaunch")
    )


# 8. a <param> that reaches no node


def test_a_param_given_to_no_node_is_one_warning_naming_it(capsys, tmp_path):
    seed = ros1_file(  # seed 000's example: a file with a parameter and no node
        tmp_path, '<arg name="update_period" default="10"/>\n'
        '<param name="timing" value="$(arg update_period)"/>', "seed.launch"
    )  # fmt: skip
    status, lines, out = launch(capsys, str(seed), "update_period:=30")
    assert status == 0 and out.strip() == ""
    assert lines == [
        f"warning: {seed}:3: param 'timing' is given to no node: ROS 2 has no parameter "
        "server; put it inside a <node>"
    ]


def test_a_param_in_a_namespace_without_nodes_is_a_warning_the_others_reach_nodes(capsys, tmp_path):
    path = ros1_file(
        tmp_path,
        '<param name="shared" value="1"/>\n'
        '<group ns="empty"><param name="rate" value="2"/></group>\n'
        '<group ns="ns1">' + NODE.format('<param name="~own" value="3"/>') + "</group>",
    )
    status, lines, out = launch(capsys, str(path))
    assert status == 0
    assert lines == [
        f"warning: {path}:3: param 'rate' is given to no node: ROS 2 has no parameter "
        "server; put it inside a <node>"
    ]
    assert "param:   shared = 1" in out and "param:   own = 3" in out


def test_a_rosparam_block_that_reaches_no_node_is_one_warning(capsys, tmp_path):
    path = ros1_file(tmp_path, '<rosparam ns="gains">p: 1\ni: 2\nd: 3</rosparam>')
    status, lines, _ = launch(capsys, str(path))
    assert status == 0
    assert lines == [
        f"warning: {path}:2: param '/gains/p', '/gains/i', '/gains/d' are given to no node: "
        "ROS 2 has no parameter server; put it inside a <node>"
    ]


def test_a_set_parameter_with_no_node_after_it_is_one_warning(capsys, tmp_path):
    path = tmp_path / "test.launch.xml"
    path.write_text(
        '<launch>\n<group><set_parameter name="used" value="1"/>\n'
        '<node pkg="ros_tutorials_topic" exec="publisher"/></group>\n'
        '<set_parameter name="late" value="2"/>\n</launch>\n'
    )
    status, lines, _ = launch(capsys, str(path))
    assert status == 0 and lines == [
        f"warning: {path}:4: param 'late' is given to no node: no <node> follows it in its scope"
    ]
