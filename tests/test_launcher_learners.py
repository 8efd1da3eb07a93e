"""What learners hit following the seeds: each mistake is one clear line, before anything starts.

Every test runs the launcher's main() with --print (or resolves and plans only): no process
is started, and what is checked is what the user sees, the error line and the exit status.
"""

from __future__ import annotations

from pathlib import Path

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
