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
