"""The launcher with real processes: the ROS graph, output, respawn, required, shutdown.

Every test checks by process id and process group that nothing is left running.
"""

from __future__ import annotations

import os
import re
import signal
import sys
import time
from pathlib import Path

import pytest
from helpers import TIMEOUT, NodeProcess, run, spin_until
from rclpy.node import Node
from ros_tutorials_interfaces.msg import MsgTutorial

PYTHON = sys.executable


def _stat(pid: int) -> tuple[str, int] | None:
    """(state, process group) of a process, or None if it does not exist."""
    try:
        text = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    fields = text.rsplit(")", 1)[1].split()
    return fields[0], int(fields[2])


def alive(pid: int) -> bool:
    stat = _stat(pid)
    return stat is not None and stat[0] not in "ZX"


def group_members(pgid: int) -> list[int]:
    pids = [int(entry) for entry in os.listdir("/proc") if entry.isdigit()]
    return [pid for pid in pids if (stat := _stat(pid)) and stat[1] == pgid and stat[0] not in "ZX"]


def assert_all_gone(pids: list[int], timeout: float = TIMEOUT) -> None:
    """Wait until none of pids, nor anything in their process groups, is running."""
    assert pids, "no process ids to check"
    deadline = time.monotonic() + timeout
    while left := sorted(
        {p for p in pids if alive(p)} | {m for p in pids for m in group_members(p)}
    ):
        if time.monotonic() > deadline:
            pytest.fail(f"processes still running {timeout:.0f} s later: {left}")
        time.sleep(0.1)


def started_pids(lines: list[str]) -> dict[str, int]:
    found = (re.match(r"\[launcher\] started (\S+) \(pid (\d+)\)", line) for line in lines)
    return {match[1]: int(match[2]) for match in found if match}


def wait_started(launcher: NodeProcess, count: int) -> dict[str, int]:
    lines = launcher.wait_for_output(
        lambda lines: len(started_pids(lines)) >= count, what=f"{count} processes started"
    )
    return started_pids(lines)


def stamps(lines: list[str], label: str, word: str) -> set[tuple[int, int]]:
    """The (sec, nanosec) stamps a topic node logged, from its 'send/recieve msg = ' triples."""
    values = [
        int(line.rsplit("= ", 1)[1])
        for line in lines
        if line.startswith(f"[{label}] ") and f" {word} msg = " in line
    ]
    return {(values[i], values[i + 1]) for i in range(0, len(values) - 2, 3)}


def launch_file(tmp_path: Path, xml: str, name: str = "test.launch.xml") -> str:
    path = tmp_path / name
    path.write_text(xml)
    return str(path)


def script(tmp_path: Path, name: str, code: str) -> str:
    path = tmp_path / f"{name}.py"
    path.write_text(code)
    return f"{PYTHON} {path}"


def test_union_launch_groups_talk_only_within_their_namespace(node_process, context, executor):
    launcher = node_process("-m", "launcher", "union.launch")
    probe = Node("probe", context=context)
    executor.add_node(probe)
    expected = {
        (name, ns) for name in ("topic_publisher", "topic_subscriber") for ns in ("/ns1", "/ns2")
    }
    spin_until(
        executor,
        lambda: expected <= set(probe.get_node_names_and_namespaces()),
        what="the four nodes in /ns1 and /ns2 in the ROS graph",
    )
    heard: dict[str, list[MsgTutorial]] = {"/ns1": [], "/ns2": []}
    for ns, messages in heard.items():
        probe.create_subscription(MsgTutorial, f"{ns}/ros_tutorial_msg", messages.append, 100)
    spin_until(executor, lambda: all(len(m) >= 3 for m in heard.values()), what="both topics")
    for ns in heard:
        assert probe.count_publishers(f"{ns}/ros_tutorial_msg") == 1
    assert probe.count_publishers("/ros_tutorial_msg") == 0

    def own_group_only(lines: list[str]) -> bool:
        for ns in ("ns1", "ns2"):
            received = stamps(lines, f"{ns}/topic_subscriber", "recieve")
            if len(received) < 3 or not received <= stamps(lines, f"{ns}/topic_publisher", "send"):
                return False
        return True

    lines = launcher.wait_for_output(own_group_only, what="each subscriber hearing its publisher")
    for ns, other in (("ns1", "ns2"), ("ns2", "ns1")):
        received = stamps(lines, f"{ns}/topic_subscriber", "recieve")
        assert not received & stamps(lines, f"{other}/topic_publisher", "send")

    pids = list(started_pids(lines).values())
    assert len(pids) == 4
    assert launcher.interrupt() == 130
    assert "[launcher] all 4 process(es) stopped" in launcher.output
    assert_all_gone(pids)


def test_first_union_launch_every_subscriber_hears_both_publishers(node_process):
    launcher = node_process("-m", "launcher", "ros_tutorials_topic", "union_no_groups.launch")

    def hears_both(lines: list[str]) -> bool:
        sent = [stamps(lines, f"topic_publisher{n}", "send") for n in (1, 2)]
        return all(
            stamps(lines, f"topic_subscriber{n}", "recieve") & own for n in (1, 2) for own in sent
        )

    launcher.wait_for_output(hears_both, what="each subscriber hearing both publishers")
    pids = list(started_pids(launcher.lines).values())
    assert launcher.interrupt() == 130
    assert_all_gone(pids)


def test_sigkill_of_the_launcher_leaves_no_children_or_grandchildren(node_process, tmp_path):
    xml = (
        "<launch>\n"
        '  <node pkg="ros_tutorials_topic" exec="talker"/>\n'
        "  <executable cmd=\"sh -c 'sleep 600 &amp; echo grandchild $! ; wait'\" "
        'name="parent" output="screen"/>\n'
        "</launch>\n"
    )
    launcher = node_process("-m", "launcher", launch_file(tmp_path, xml))
    lines = launcher.wait_for_output(
        lambda lines: any("grandchild" in line for line in lines) and len(started_pids(lines)) == 2,
        what="both processes and the grandchild",
    )
    grandchild = int(next(line for line in lines if "grandchild" in line).split()[-1])
    pids = [*started_pids(lines).values(), grandchild]
    assert all(alive(pid) for pid in pids)

    os.kill(launcher.process.pid, signal.SIGKILL)
    assert launcher.wait() == -signal.SIGKILL
    assert_all_gone(pids)


def test_sigterm_escalates_for_a_child_that_ignores_sigint(node_process, tmp_path):
    stubborn = script(
        tmp_path,
        "stubborn",
        "import signal, time\nsignal.signal(signal.SIGINT, signal.SIG_IGN)\n"
        "print('ready', flush=True)\ntime.sleep(600)\n",
    )
    xml = (
        f'<launch><executable cmd="{stubborn}" name="stubborn" output="screen" '
        'sigterm_timeout="1"/></launch>'
    )
    launcher = node_process("-m", "launcher", launch_file(tmp_path, xml))
    lines = launcher.wait_for_output(  # the child's line may come before the launcher's
        lambda lines: "[stubborn] ready" in lines and started_pids(lines), what="ready, its pid"
    )
    pids = list(started_pids(lines).values())
    launcher.process.send_signal(signal.SIGTERM)
    assert launcher.wait() == 143
    assert "[launcher] stubborn still running after SIGINT: sending SIGTERM" in launcher.output
    assert_all_gone(pids)


def test_ros2_launch_says_the_escalation_as_ros2_launch(node_process, tmp_path):
    # ros2 launch (launch/actions/execute_local.py) logs each step of the escalation as an
    # error naming the seconds since the SIGINT, then the signal it sends.
    stubborn = script(
        tmp_path,
        "stubborn",
        "import signal, time\nsignal.signal(signal.SIGINT, signal.SIG_IGN)\n"
        "signal.signal(signal.SIGTERM, signal.SIG_IGN)\nprint('ready', flush=True)\n"
        "time.sleep(600)\n",
    )
    xml = (
        f'<launch><executable cmd="{stubborn}" name="stubborn" output="screen" '
        'sigterm_timeout="1" sigkill_timeout="1"/></launch>'
    )
    launcher = node_process("-m", "ros2cmd", "launch", launch_file(tmp_path, xml))
    lines = launcher.wait_for_output(
        lambda lines: (
            "[stubborn-1] ready" in lines
            and any("process started with pid" in line for line in lines)
        ),
        what="ready, its pid",
    )
    started = re.search(r"\[stubborn-1\]: process started with pid \[(\d+)\]", "\n".join(lines))
    assert started is not None, lines
    pid = int(started[1])
    launcher.process.send_signal(signal.SIGINT)
    launcher.wait()
    lines = launcher.output.splitlines()
    expected = [
        "[ERROR] [stubborn-1]: process[stubborn-1] failed to terminate '1' seconds after "
        "receiving 'SIGINT', escalating to 'SIGTERM'",
        "[INFO] [stubborn-1]: sending signal 'SIGTERM' to process[stubborn-1]",
        "[ERROR] [stubborn-1]: process[stubborn-1] failed to terminate '2.0' seconds after "
        "receiving 'SIGTERM', escalating to 'SIGKILL'",
        "[INFO] [stubborn-1]: sending signal 'SIGKILL' to process[stubborn-1]",
    ]
    assert [line for line in lines if line in expected] == expected
    assert not any("still running after" in line for line in lines)
    assert_all_gone([pid])


def test_respawn_backs_off_and_gives_up_after_max_retries(node_process, tmp_path):
    crash = script(tmp_path, "crash", "print('run', flush=True)\nraise SystemExit(3)\n")
    xml = (
        f'<launch><executable cmd="{crash}" name="crash" output="screen" respawn="true" '
        'respawn_max_retries="2"/></launch>'
    )
    launcher = node_process("-m", "launcher", launch_file(tmp_path, xml))
    assert launcher.wait() == 1
    output = launcher.output
    assert output.count("[crash] run") == 3
    assert "[launcher] crash died with exit code 3; respawning in 0.5 s" in output
    assert "[launcher] crash died with exit code 3; respawning in 1.0 s" in output
    assert "not respawning it after 2 quick restarts in a row" in output


def test_required_node_failure_ends_the_launch_with_exit_code_1(node_process, tmp_path):
    xml = (
        "<launch>\n"
        '  <node pkg="ros_tutorials_topic" type="talker" name="talker"/>\n'
        '  <node pkg="ros_tutorials_service" type="add_two_ints_client" name="crasher"\n'
        '        required="true" args="one two"/>\n'
        "</launch>\n"
    )
    launcher = node_process("-m", "launcher", launch_file(tmp_path, xml, "test.launch"))
    assert launcher.wait() == 1
    output = launcher.output
    assert "[launcher] crasher died with exit code 2; it is required, so the launch ends" in output
    assert "[crasher] usage: add_two_ints_client" in output
    assert_all_gone(list(started_pids(launcher.lines).values()))


def test_args_that_rcl_cannot_parse_are_refused_before_anything_starts(tmp_path):
    xml = (
        '<launch>\n  <node pkg="ros_tutorials_topic" type="talker" name="talker"/>\n'
        '  <node pkg="ros_tutorials_topic" type="listener" name="l" args="--ros-args -r bad"/>\n'
        "</launch>\n"
    )
    result = run("roslaunch", launch_file(tmp_path, xml, "t.launch"))
    assert result.returncode == 1 and not result.stdout, result
    assert result.stderr.endswith(
        "t.launch:3: args: invalid ROS argument '-r bad': a remap is FROM:=TO\n"
    ), result.stderr


def test_on_exit_shutdown_after_a_clean_exit_ends_with_code_0(node_process, tmp_path):
    done = script(tmp_path, "done", "import time\ntime.sleep(1)\nprint('done')\n")
    xml = (
        '<launch><node pkg="ros_tutorials_topic" exec="listener"/>'
        f'<executable cmd="{done}" name="done" output="screen" on_exit="shutdown"/></launch>'
    )
    launcher = node_process("-m", "launcher", launch_file(tmp_path, xml))
    assert launcher.wait() == 0
    assert "[done] done" in launcher.output
    assert "[launcher] done exited cleanly; it is required, so the launch ends" in launcher.output
    assert "[launcher] all 1 process(es) stopped" in launcher.output
    assert_all_gone(list(started_pids(launcher.lines).values()))


def test_on_shutdown_runs_its_function_and_cancels_its_timer(node_process, tmp_path):
    # ros2 launch: a TimerAction cancels itself at shutdown, one made by OnShutdown too.
    sleeper = script(
        tmp_path, "sleeper", "import time\nprint('ready', flush=True)\ntime.sleep(600)\n"
    )
    marker = tmp_path / "cleaned"
    path = tmp_path / "t.launch.py"
    path.write_text(
        "from pathlib import Path\n"
        "from launch import LaunchDescription\n"
        "from launch.actions import ExecuteProcess, LogInfo, OpaqueFunction\n"
        "from launch.actions import RegisterEventHandler, TimerAction\n"
        "from launch.event_handlers import OnShutdown\n\n"
        f"def cleanup(context):\n    Path({str(marker)!r}).write_text('cleaned')\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        f"        ExecuteProcess(cmd={sleeper.split()!r}, name='sleeper', output='screen'),\n"
        "        RegisterEventHandler(OnShutdown(on_shutdown=[\n"
        "            LogInfo(msg='cleaning up'),\n"
        "            OpaqueFunction(function=cleanup),\n"
        "            TimerAction(period=100.0, actions=[LogInfo(msg='timer fired')]),\n"
        "        ])),\n"
        "    ])\n"
    )
    launcher = node_process("-m", "launcher", str(path))
    lines = launcher.wait_for_output(
        lambda lines: "[sleeper] ready" in lines and started_pids(lines), what="ready, its pid"
    )
    launcher.process.send_signal(signal.SIGINT)
    assert launcher.wait() == 130
    assert "cleaning up" in launcher.output
    assert "timer fired" not in launcher.output
    assert marker.read_text() == "cleaned"  # the handler's function, at the shutdown
    assert_all_gone(list(started_pids(lines).values()))


def test_log_output_goes_to_the_log_folder_and_stderr_to_the_screen(node_process, tmp_path):
    say = script(
        tmp_path, "say", "import sys\nprint('to stdout')\nprint('to stderr', file=sys.stderr)\n"
    )
    failing = script(tmp_path, "failing", "raise SystemExit(2)\n")
    xml = (
        f'<launch><executable cmd="{say}" name="say"/>'
        f'<executable cmd="{failing}" name="failing"/></launch>'
    )
    launcher = node_process("-m", "launcher", launch_file(tmp_path, xml))
    assert launcher.wait() == 1  # failing ended with 2: not a clean launch
    output = launcher.output
    assert "[say] to stderr" in output and "to stdout" not in output
    assert "[launcher] failing died with exit code 2" in output
    log_dir = Path(re.search(r"\[launcher\] logging to (\S+)", output)[1])
    assert log_dir.parent == Path(os.environ["ROS_LOG_DIR"])
    assert (log_dir / "say.log").read_text().splitlines() in (
        ["to stdout", "to stderr"],
        ["to stderr", "to stdout"],
    )


def test_output_format_is_how_each_line_is_shown(node_process, tmp_path):
    # ros2 launch's ExecuteProcess(output_format=...): str.format with {line} and {this...}
    ok = script(tmp_path, "ok", "print('fine')\n")
    py = (
        "from launch import LaunchDescription\nfrom launch.actions import ExecuteProcess\n"
        "def generate_launch_description():\n    return LaunchDescription([ExecuteProcess(\n"
        f"        cmd={ok.split()!r}, name='ok', output='screen',\n"
        "        output_format='{line} <- {this.process_description.final_name}')])\n"
    )
    launcher = node_process("-m", "launcher", launch_file(tmp_path, py, "test.launch.py"))
    assert launcher.wait() == 0
    assert "fine <- ok" in launcher.lines and "[ok] fine" not in launcher.output


def test_clean_launch_exits_0(node_process, tmp_path):
    ok = script(tmp_path, "ok", "print('fine')\n")
    launcher = node_process(
        "-m",
        "launcher",
        launch_file(tmp_path, f'<launch><executable cmd="{ok}" name="ok"/></launch>'),
    )
    assert launcher.wait() == 0
    assert "[launcher] ok exited cleanly" in launcher.output


def test_command_line_errors_are_one_line_and_exit_1(node_process, tmp_path):
    cases = [
        (
            ["nothing.launch"],
            "error: no launch file 'nothing.launch' here or in any package; known:",
        ),
        (["union.launch", "who:=x"], "no argument named who is declared (declared: none)"),
        (["union.launch", "bad-name:=x"], "error: malformed argument 'bad-name:=x'"),
        (["nope", "union.launch"], "error: unknown package 'nope'; known packages:"),
    ]
    for words, expected in cases:
        run = node_process("-m", "launcher", *words)
        assert run.wait() == 1, words
        assert expected in run.output and "Traceback" not in run.output
        assert len(run.lines) == 1, run.output


def test_print_and_show_args_start_nothing(node_process):
    printed = node_process("-m", "launcher", "union.launch", "--print")
    assert printed.wait() == 0
    assert "[ns2/topic_subscriber]" in printed.output
    command = (
        "-m ros_tutorials_topic.subscriber --ros-args -r __node:=topic_subscriber -r __ns:=/ns2"
    )
    assert command in printed.output
    assert "[launcher] started" not in printed.output
    shown = node_process("-m", "launcher", "ros_tutorials_topic", "union.launch", "--show-args")
    assert shown.wait() == 0
    assert shown.output == "This launch file has no arguments."


def test_ros2_launch_speaks_as_ros2_launch(node_process, tmp_path):
    # Creating-Launch-Files shows `[INFO] [turtlesim_node-1]: process started with pid [11714]`:
    # each process named after its program (or its name=) and numbered as they start.
    say = script(tmp_path, "say", "import sys\nprint('to stderr', file=sys.stderr)\n")
    failing = script(tmp_path, "failing", "raise SystemExit(2)\n")
    xml = f'<launch><executable cmd="{say}"/><executable cmd="{failing}" name="fails"/></launch>'
    launcher = node_process("-m", "ros2cmd", "launch", launch_file(tmp_path, xml))
    assert launcher.wait() == 1
    lines = launcher.output.splitlines()
    log_dir = re.escape(os.environ["ROS_LOG_DIR"])
    assert re.fullmatch(
        rf"\[INFO\] \[launch\]: All log files can be found below {log_dir}/"
        r"\d{4}-\d\d-\d\d-\d\d-\d\d-\d\d-\d{6}-.+-\d+",
        lines[0],
    )
    assert lines[1] == "[INFO] [launch]: Default logging verbosity is set to INFO"
    pids = {name: int(pid) for name, pid in re.findall(r"\[(\S+)\]: process started with pid "
                                                       r"\[(\d+)\]", launcher.output)}  # fmt: skip
    assert sorted(pids) == ["fails-2", "python-1"]  # the program of `python say.py`
    assert "[python-1] to stderr" in lines
    assert f"[INFO] [python-1]: process has finished cleanly [pid {pids['python-1']}]" in lines
    assert (
        f"[ERROR] [fails-2]: process has died [pid {pids['fails-2']}, exit code 2, "
        f"cmd '{failing}']."
    ) in lines
