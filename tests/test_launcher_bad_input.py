"""The launcher under bad input and rough handling: one clear line, bounded memory, no orphan.

Each bad launch file is run through the real command line (``python -m launcher FILE
--print``), as a user would: exit status 1, one ``error: FILE:LINE: ...`` line, no traceback.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import TIMEOUT
from test_launcher_run import alive, assert_all_gone, launch_file, wait_started

PYTHON = sys.executable
NODE = '<node pkg="ros_tutorials_topic" type="topic_publisher" name="pub" {}/>'
BOMB = "\n".join(
    ['a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol"]']
    + [
        f"{name}: &{name} [{', '.join([f'*{prev}'] * 9)}]"
        for prev, name in zip("abcdefgh", "bcdefghi", strict=True)
    ]
)


def run_launcher(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    return subprocess.run(
        [PYTHON, "-m", "launcher", *args],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
        env={**os.environ, **(env or {})},
    )


def refused(path: Path, *args: str, env: dict[str, str] | None = None) -> str:
    """Run the launcher on path; it must refuse with exactly one error line. That line."""
    done = run_launcher(str(path), *args, "--print", env=env)
    assert "Traceback" not in done.stderr, done.stderr
    assert done.returncode == 1, (done.stdout, done.stderr)
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), done.stderr
    return lines[0]


def ros1_file(tmp_path: Path, body: str, name: str = "test.launch") -> Path:
    path = tmp_path / name
    path.write_text(f"<launch>\n{body}\n</launch>\n")
    return path


@pytest.mark.parametrize(
    "attribute",
    ['args="\'unclosed"', 'launch-prefix="nice \'-n"', 'ros_args="\'x"', "cmd"],
)
def test_unclosed_quotes_are_one_line_with_file_and_line(tmp_path, attribute):
    if attribute == "cmd":
        path = tmp_path / "test.launch.xml"
        path.write_text('<launch>\n<executable cmd="echo \'hi"/>\n</launch>\n')
    elif attribute.startswith("ros_args"):
        path = tmp_path / "test.launch.xml"
        body = f'<node pkg="ros_tutorials_topic" exec="topic_publisher" {attribute}/>'
        path.write_text(f"<launch>\n{body}\n</launch>\n")
    else:
        path = ros1_file(tmp_path, NODE.format(attribute))
    line = refused(path)
    assert f"{path}:2:" in line and "No closing quotation" in line


def test_unclosed_quote_in_a_command_line_argument_value(tmp_path):
    path = ros1_file(tmp_path, '<arg name="x" default=""/>' + NODE.format('args="$(arg x)"'))
    line = refused(path, "x:='oops")
    assert f"{path}:2:" in line and "No closing quotation" in line


def test_rosparam_with_a_yaml_date_is_refused(tmp_path):
    path = ros1_file(tmp_path, "<rosparam>when: 2024-01-01</rosparam>")
    line = refused(path)
    assert f"{path}:2:" in line and "is a YAML date" in line


def test_params_file_that_is_not_utf8_is_refused(tmp_path):
    (tmp_path / "bad.yaml").write_bytes(b"name: caf\xe9\n")
    path = ros1_file(tmp_path, '<rosparam file="bad.yaml"/>')
    line = refused(path)
    assert f"{path}:2:" in line and "not UTF-8" in line


@pytest.mark.parametrize("name", ["A=B", ""])
def test_env_name_with_equals_or_empty_is_refused(tmp_path, name):
    path = ros1_file(tmp_path, f'<node pkg="ros_tutorials_topic" type="topic_publisher" name="p">'
                               f'<env name="{name}" value="1"/></node>')  # fmt: skip
    assert "invalid environment variable name" in refused(path)


def test_unwritable_log_dir_is_one_line(tmp_path):
    path = ros1_file(tmp_path, NODE.format(""))
    blocker = tmp_path / "a_file"
    blocker.write_text("")
    done = run_launcher(str(path), env={"ROS_LOG_DIR": str(blocker / "logs")})
    assert "Traceback" not in done.stderr and done.returncode == 1, done.stderr
    assert done.stderr.strip().splitlines() == [
        line for line in done.stderr.strip().splitlines() if line.startswith("error: ")
    ]
    # What `ros2 run` says too (ros_tutorials_common/dds.py environment_problem).
    assert f"cannot write ROS log files to '{blocker / 'logs'}' (ROS_LOG_DIR)" in done.stderr
    assert "started" not in done.stdout  # nothing ran


def test_self_include_names_the_include_line(tmp_path):
    path = ros1_file(tmp_path, '<include file="test.launch"/>')
    line = refused(path)
    assert f"{path}:2: launch files include each other in a loop" in line


def test_groups_nested_too_deeply_name_file_and_line(tmp_path):
    body = '<group ns="g">' * 80 + NODE.format("") + "</group>" * 80
    line = refused(ros1_file(tmp_path, body))
    assert "test.launch:2: groups and includes nested more than 50 deep" in line


def test_substitutions_nested_too_deeply_name_file_and_line(tmp_path):
    text = "$(optenv X " * 300 + ")" * 300
    path = ros1_file(tmp_path, NODE.format(f'args="{text}"'))
    assert f"{path}:2: substitutions nested more than" in refused(path)


def test_namespace_with_an_empty_part_is_refused(tmp_path):
    line = refused(ros1_file(tmp_path, '<group ns="bad//ns">' + NODE.format("") + "</group>"))
    assert "invalid namespace 'bad//ns'" in line


def test_respawn_delay_beyond_a_day_is_refused(tmp_path):
    line = refused(ros1_file(tmp_path, NODE.format('respawn="true" respawn_delay="1e308"')))
    assert "'respawn_delay' is 1e308 s; at most 86400 s" in line


def test_a_program_that_is_not_executable_is_named_so(tmp_path):
    program = tmp_path / "tool.sh"
    program.write_text("#!/bin/sh\necho hi\n")
    program.chmod(0o644)
    path = tmp_path / "test.launch.xml"
    path.write_text(f'<launch>\n<executable cmd="{program}"/>\n</launch>\n')
    line = refused(path)
    assert f"program '{program}' is not executable" in line
    program.chmod(0o755)
    assert run_launcher(str(path), "--print").returncode == 0


def _params_file_launch(tmp_path: Path, content: str) -> Path:
    (tmp_path / "p.yaml").write_text(content)
    path = tmp_path / "test.launch.xml"
    node = '<node pkg="ros_tutorials_topic" exec="topic_publisher"><param from="p.yaml"/></node>'
    path.write_text(f"<launch>\n{node}\n</launch>\n")
    return path


def test_a_params_file_that_is_no_params_file_is_refused_before_anything_starts(tmp_path):
    path = _params_file_launch(tmp_path, "7:\n  ros__parameters:\n    a: 1\n")
    line = refused(path)
    assert f"{path}:2:" in line and "is not a string" in line


@pytest.mark.parametrize(
    ("content", "expected"),
    [
        ("/**:\n  ros__parameters:\n    1: 2\n", "is not a string"),
        ("/**:\n  ros__parameters:\n    big: 99999999999999999999\n", "does not fit"),
        ("/**:\n  ros__parameters:\n    when: 2024-01-01\n", "is a YAML date"),
    ],
)
def test_a_value_rcl_will_refuse_in_a_params_file_is_warned_before_anything_starts(
    tmp_path, content, expected
):
    """ros2 launch passes a parameters file to the node as its path, and rcl refuses what it
    cannot read when the node starts; the launcher says so once, before anything starts."""
    path = _params_file_launch(tmp_path, content)
    done = run_launcher(str(path), "--print")
    assert done.returncode == 0 and "Traceback" not in done.stderr, done.stderr
    warned = [line for line in done.stderr.splitlines() if f"{path}:2:" in line]
    assert len(warned) == 1 and expected in warned[0], done.stderr
    assert "where rcl will refuse it" in warned[0]


def test_integers_beyond_int64_in_params_are_refused(tmp_path):
    line = refused(ros1_file(tmp_path, '<param name="x" value="99999999999999999999"/>'))
    assert "does not fit a ROS integer (int64)" in line
    line = refused(ros1_file(tmp_path, "<rosparam>x: [1, 99999999999999999999]</rosparam>"))
    assert "does not fit" in line


def test_rosparam_from_dev_zero_is_refused_within_the_size_limit(tmp_path):
    line = refused(ros1_file(tmp_path, '<rosparam file="/dev/zero"/>'))
    assert "/dev/zero is larger than 1 MiB" in line


def test_yaml_alias_bomb_in_rosparam_is_refused(tmp_path):
    assert len(BOMB) < 600  # the was 507 bytes
    xml_text = BOMB.replace("&", "&amp;")
    line = refused(ros1_file(tmp_path, f"<rosparam>\n{xml_text}\n</rosparam>"))
    assert "once its aliases are expanded" in line


def test_a_launch_file_over_the_size_limit_is_refused(tmp_path):
    path = ros1_file(tmp_path, "<!--" + "x" * (1024 * 1024) + "-->")
    assert "is larger than 1 MiB" in refused(path)


# -- processes ---------------------------------------------------------------------------------


def test_ctrl_c_while_children_import_prints_no_traceback(node_process):
    """SIGINT as soon as the four children exist: they are still importing rclpy."""
    launcher = node_process("-m", "launcher", "union.launch")
    pids = list(wait_started(launcher, 4).values())
    assert launcher.interrupt() == 130, launcher.output
    assert "Traceback" not in launcher.output, launcher.output
    assert "KeyboardInterrupt" not in launcher.output
    assert_all_gone(pids)


GRANDCHILD = """
import os, subprocess, sys, time
pid_file = sys.argv[1]
# A grandchild that leaves the process group and session of its parent (setsid).
child = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(600)"],
                         start_new_session=True)
with open(pid_file, "w") as f:
    f.write(str(child.pid))
print("grandchild started", flush=True)
time.sleep(600)
"""


def test_a_grandchild_that_calls_setsid_is_stopped_too(node_process, tmp_path):
    script = tmp_path / "spawner.py"
    script.write_text(GRANDCHILD)
    pid_file = tmp_path / "grandchild.pid"
    path = launch_file(
        tmp_path,
        f'<launch><executable cmd="{PYTHON} {script} {pid_file}" output="screen"/></launch>',
    )
    launcher = node_process("-m", "launcher", path)
    pids = list(wait_started(launcher, 1).values())
    launcher.wait_for_output(
        lambda lines: any("grandchild started" in line for line in lines), what="the grandchild"
    )
    grandchild = int(pid_file.read_text())
    assert alive(grandchild)
    try:
        assert launcher.interrupt() == 130
        assert_all_gone([*pids, grandchild])
        assert "left their group" in launcher.output
    finally:
        if alive(grandchild):
            os.kill(grandchild, signal.SIGKILL)


LONG_LINE = """
import sys
chunk = b"x" * (1024 * 1024)
for _ in range({mib}):
    sys.stdout.buffer.write(chunk)
sys.stdout.buffer.write(b"\\nafter the long line\\n")
sys.stdout.flush()
import time; time.sleep(600)
"""


def _peak_rss_mib(pid: int) -> float:
    with open(f"/proc/{pid}/status") as status:
        for line in status:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024
    raise AssertionError("no VmHWM")


def test_a_huge_line_without_newline_is_cut_and_memory_stays_bounded(node_process, tmp_path):
    mib = 100
    script = tmp_path / "long_line.py"
    script.write_text(LONG_LINE.format(mib=mib))
    path = launch_file(
        tmp_path, f'<launch><executable cmd="{PYTHON} {script}" output="screen"/></launch>'
    )
    launcher = node_process("-m", "launcher", path)
    pids = list(wait_started(launcher, 1).values())
    lines = launcher.wait_for_output(
        lambda lines: any("after the long line" in line for line in lines),
        timeout=120,
        what="the line after the long one",
    )
    # The launcher is the child's parent (the pid we started is its guardian, launcher/guardian.py).
    inner = int(Path(f"/proc/{pids[0]}/stat").read_text().rsplit(")", 1)[1].split()[1])
    assert inner != launcher.process.pid
    peak = _peak_rss_mib(inner)
    assert peak < 80, f"the launcher's peak memory was {peak:.0f} MiB for a {mib} MiB line"
    cut = [line for line in lines if "[line cut at 65536 bytes" in line]
    assert len(cut) == 1 and len(cut[0]) < 70_000
    log_dir = next(line for line in lines if "logging to" in line).split("logging to ")[1]
    logged = sum(p.stat().st_size for p in Path(log_dir).glob("*.log"))
    assert logged >= mib * 1024 * 1024  # the log file has the whole line
    assert launcher.interrupt() == 130
    assert_all_gone(pids)
    for log in Path(log_dir).glob("*.log"):
        log.unlink()


def test_command_substitution_output_is_bounded(tmp_path):
    path = tmp_path / "t.launch.xml"
    path.write_text('<launch>\n<let name="x" value="$(command yes)"/>\n</launch>\n')
    done = run_launcher(str(path), "--print", "--allow-code")
    assert done.returncode == 1 and "Traceback" not in done.stderr, done.stderr
    assert f"{path}:2: $(command yes) printed more than 1 MiB" in done.stderr


@pytest.mark.parametrize(
    ("body", "expected"),
    [
        (
            '<group ns="nsü"><node pkg="turtlesim" type="turtlesim_node" name="sim"/></group>',
            "invalid namespace 'nsü'",
        ),
        ('<node pkg="turtlesim" type="turtlesim_node" name="pé"/>', "invalid node name 'pé'"),
    ],
)
def test_non_ascii_names_are_refused_before_anything_starts(tmp_path, body, expected):
    """rcl takes ASCII letters, digits and _ only; str.isalnum() took 'é' and the node failed
    at run time with rcl's raw message."""
    assert expected in refused(ros1_file(tmp_path, body))


def _tenfold(tmp_path: Path, ros2: bool) -> Path:
    """Ten levels of arguments whose defaults repeat the one before ten times (1.3 KB):
    10^11 characters at the last level, which took the launcher to 10.8 GB."""
    declare, use = (
        ('<let name="a{i}" value="{v}"/>', "$(var a{i})")
        if ros2
        else ('<arg name="a{i}" default="{v}"/>', "$(arg a{i})")
    )
    lines = [declare.format(i=0, v="x" * 10)]
    lines += [declare.format(i=i, v=use.format(i=i - 1) * 10) for i in range(1, 11)]
    exec_attr = "exec" if ros2 else "type"
    lines.append(
        f'<node pkg="turtlesim" {exec_attr}="turtlesim_node" name="sim" args="{use.format(i=10)}"/>'
    )
    return ros1_file(tmp_path, "\n".join(lines), "bomb.launch.xml" if ros2 else "bomb.launch")


@pytest.mark.parametrize("ros2", [False, True], ids=["ros1 arg", "ros2 let"])
def test_substitutions_that_expand_without_bound_are_refused(tmp_path, ros2):
    line = refused(_tenfold(tmp_path, ros2))
    assert "substitutions expand to more than 1,048,576 characters" in line


def test_a_log_file_that_cannot_be_written_is_said_once_and_output_goes_on():
    """A full disk (/dev/full: every write fails with ENOSPC) ended the thread that relays a
    child's output to the screen; now the log says so once and the relay carries on."""
    from launcher.supervise import LogSink

    said: list[str] = []
    sinks = [LogSink(Path("/dev/full"), "ns1/talker", said.append) for _ in range(2)]
    for sink in sinks:  # stdout's and stderr's: one file, one message
        for _ in range(3):
            sink.write(b"hello world\n" * 1000)
        sink.close()
    assert len(said) == 1 and "No space left on device" in said[0] and "ns1/talker" in said[0]


# The official Jazzy tutorial's `main`: no try around spin, so Ctrl-C ends it in a traceback.
SPINNING_NODE = """
import rclpy
from rclpy.node import Node
rclpy.init()
node = Node("plain_spinner")
print("spinning", flush=True)
rclpy.spin(node)
"""


def test_ctrl_c_of_a_running_node_without_a_handler_is_one_line(node_process, tmp_path):
    program = tmp_path / "spinner.py"
    program.write_text(SPINNING_NODE)
    path = launch_file(
        tmp_path,
        f'<launch><executable cmd="{PYTHON} {program}" name="spinner" output="screen"/></launch>',
    )
    launcher = node_process("-m", "launcher", path)
    pids = list(wait_started(launcher, 1).values())
    launcher.wait_for_text("[spinner] spinning")
    assert launcher.interrupt() == 130, launcher.output
    assert_all_gone(pids)
    assert "[spinner] stopped (its traceback is in the log)" in launcher.output
    assert "Traceback" not in launcher.output, launcher.output
    assert "KeyboardInterrupt" not in launcher.output
