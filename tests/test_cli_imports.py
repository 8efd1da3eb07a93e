"""What `ros2` loads: help, parsing and the daemon's answers go without rclpy (issue 39).

rclpy takes about 0.1 s to load, rclpy.action 0.15 s more (numpy), and a command's help or a
list the daemon answers needs neither: the verbs' modules import rclpy, the message packages
and rosidl_parser inside the functions that run a command (docs/dev/architecture.md). These
tests run the command in a fresh interpreter and read ``sys.modules`` as it exits; they are
the guard that keeps the answers fast (the timings are in benchmarks/daemon.py).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time

import pytest
from helpers import TIMEOUT

from ros2cmd import cli
from ros2cmd.daemon import client as daemon

# What a command's help, parsing or daemon answer must not load.
HEAVY = ("rclpy", "numpy", "rosidl_parser", "action_msgs", "rcl_interfaces", "rmw_dds_common")

# Runs ENTRY (module:function) with the arguments, and prints the heavy modules loaded, at exit.
PROBE = """
import atexit, importlib, sys
heavy = set(sys.argv[2].split(","))
def report():
    loaded = sorted({m.split(".")[0] for m in sys.modules} & heavy)
    print("LOADED:" + ",".join(loaded), file=sys.stderr)
atexit.register(report)
module, function = sys.argv[1].split(":")
sys.exit(getattr(importlib.import_module(module), function)(sys.argv[3:]))
"""


def loaded(
    entry: str, *args: str, env: dict[str, str] | None = None
) -> tuple[list[str], subprocess.CompletedProcess]:
    """The heavy modules `entry ARGS` loaded, and how it ended."""
    result = subprocess.run(
        [sys.executable, "-c", PROBE, entry, ",".join(HEAVY), *args],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
        env=env,
        stdin=subprocess.DEVNULL,
    )
    assert "Traceback" not in result.stderr, result.stderr
    lines = [line for line in result.stderr.splitlines() if line.startswith("LOADED:")]
    assert lines, f"the probe did not report:\n{result.stderr}"
    modules = lines[-1].removeprefix("LOADED:")
    return (modules.split(",") if modules else []), result


VERBS = ("action", "bag", "daemon", "doctor", "interface", "node", "param", "pkg", "run")
VERBS += ("service", "topic")


@pytest.mark.parametrize(
    "args",
    [
        ["-h"],
        *([verb, "-h"] for verb in VERBS),
        ["topic", "echo", "-h"],
        ["topic", "pub", "-h"],
        ["action", "send_goal", "-h"],
        ["param", "set", "-h"],
        ["service", "call", "-h"],
        ["bag", "record", "-h"],
    ],
    ids=" ".join,
)
def test_help_loads_no_rclpy(args):
    modules, result = loaded("ros2cmd.entry:main", *args)
    assert result.returncode == 0 and result.stdout.startswith("usage: ros2")
    assert modules == [], f"`ros2 {' '.join(args)}` loaded {modules}"


@pytest.mark.parametrize(
    ("entry", "args"),
    [
        ("ros2cmd.ros1.rostopic:rostopic", ["-h"]),
        ("ros2cmd.ros1.rostopic:rostopic", ["pub", "-h"]),
        ("ros2cmd.ros1.rosnode:rosnode", ["-h"]),
        ("ros2cmd.ros1.rosservice:rosservice", ["-h"]),
        ("ros2cmd.ros1.rosparam:rosparam", ["-h"]),
        ("ros2cmd.ros1.rosmsg:rosmsg", ["-h"]),
        ("ros2cmd.ros1.rosrun:rosrun", ["-h"]),
    ],
    ids=lambda value: value if isinstance(value, str) else " ".join(value),
)
def test_ros1_help_loads_no_rclpy(entry, args):
    modules, result = loaded(entry, *args)
    assert result.returncode == 0 and result.stdout.startswith("usage:"), result.stderr
    assert modules == [], f"{entry} {' '.join(args)} loaded {modules}"


# Every verb's command line, parsed (what TAB completion does too): the whole parser is built
# and each command's options are read, nothing run.
PARSE_EVERY_VERB = """
import sys
from ros2cmd.cli import build_parser
parser = build_parser()
for line in sys.argv[1:]:
    parser.parse_args(line.split())
loaded = sorted({m.split(".")[0] for m in sys.modules} & set(%r))
print(",".join(loaded))
"""

COMMAND_LINES = (
    "topic echo /chatter std_msgs/msg/String --qos-profile sensor_data --qos-depth 5",
    "topic pub -r 2 /chatter std_msgs/msg/String {{}} --qos-reliability reliable",
    "topic info -v /chatter",
    "topic hz /chatter",
    "topic delay /chatter",
    "topic bw /chatter",
    "topic list -t",
    "node info /talker",
    "service call /srv std_srvs/srv/Empty",
    "service echo /srv",
    "param set /node p 1",
    "param get /node p",
    "param dump /node",
    "param delete /node p",
    "param describe /node p",
    "param list",
    "action send_goal /a pkg/action/A {{}}",
    "action list -t",
    "interface show std_msgs/msg/String",
    "interface list",
    "bag record -a",
    "bag play {bag}",
    "bag info {bag}",
    "pkg create my_pkg",
    "pkg xml std_msgs",
    "doctor --report",
    "run some_pkg some_exe arg",
    "daemon status",
)


def test_parsing_every_verb_loads_no_rclpy(tmp_path):
    lines = [line.format(bag=tmp_path) for line in COMMAND_LINES]  # a bag's path must exist
    result = subprocess.run(
        [sys.executable, "-c", PARSE_EVERY_VERB % (HEAVY,), *lines],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "", f"parsing loaded {result.stdout.strip()}"


def test_the_qos_choices_are_rclpys():
    """The --qos-* choices are written out (no rclpy to build the parser): they are rclpy's."""
    from rclpy.qos import (
        DurabilityPolicy,
        HistoryPolicy,
        LivelinessPolicy,
        QoSPresetProfiles,
        ReliabilityPolicy,
    )

    from ros2cmd.qos import POLICY_KEYS, PROFILE_HISTORY

    assert list(PROFILE_HISTORY) == QoSPresetProfiles.short_keys()
    for profile, history in PROFILE_HISTORY.items():
        assert QoSPresetProfiles.get_from_short_key(profile).history.short_key == history
    for name, policy in (
        ("history", HistoryPolicy),
        ("reliability", ReliabilityPolicy),
        ("durability", DurabilityPolicy),
        ("liveliness", LivelinessPolicy),
    ):
        assert list(POLICY_KEYS[name]) == policy.short_keys(), name


def _with_daemon() -> dict[str, str]:
    env = dict(os.environ)
    env.pop(daemon.NO_DAEMON_VARIABLE, None)
    return env


@pytest.fixture
def running_daemon(ros_domain):
    """The session's daemon, started by `ros2 daemon start`; stopped after the test."""
    _, started = loaded("ros2cmd.entry:main", "daemon", "start", env=_with_daemon())
    assert started.returncode == 0, started.stderr
    try:
        yield
    finally:
        daemon.stop_quietly()


def _served_without_rclpy(*args: str) -> subprocess.CompletedProcess:
    """`ros2 ARGS` answered by the daemon: no rclpy loaded. The daemon may decline on a very
    busy machine (the command then discovers for itself, with rclpy): asked a few times."""
    tries = []
    for _ in range(5):
        modules, result = loaded("ros2cmd.entry:main", *args, env=_with_daemon())
        assert result.returncode == 0, result.stderr
        if not modules:
            return result
        tries.append(modules)
    pytest.fail(f"`ros2 {' '.join(args)}` loaded {tries[-1]} in each of {len(tries)} runs")


def _daemon_sees(node: str) -> None:
    """Wait until the daemon answers complete with the node in it (it declines while a
    process it counted has not been heard from, on a busy machine for a while)."""
    deadline = time.monotonic() + TIMEOUT
    while True:
        answer = daemon.ask_graph()
        if answer is not None and node in answer.node_names():
            return
        if time.monotonic() > deadline:
            pytest.fail(f"the daemon did not answer with {node} within {TIMEOUT:.0f} s")
        time.sleep(0.1)  # the daemon answers after its own wait: this only paces the asking


def test_what_the_daemon_answers_loads_no_rclpy(running_daemon, node_process):
    node_process("-m", "ros_tutorials_topic.publisher").wait_for_text("send msg")
    _daemon_sees("/topic_publisher")
    assert "/ros_tutorial_msg\n" in _served_without_rclpy("topic", "list").stdout
    assert "/topic_publisher\n" in _served_without_rclpy("node", "list").stdout
    info = _served_without_rclpy("node", "info", "/topic_publisher").stdout
    assert "    /ros_tutorial_msg: ros_tutorials_interfaces/msg/MsgTutorial\n" in info
    topic = _served_without_rclpy("topic", "info", "/ros_tutorial_msg").stdout
    assert topic.startswith("Type: ros_tutorials_interfaces/msg/MsgTutorial\nPublisher count: 1\n")
    type_name = _served_without_rclpy("topic", "type", "/ros_tutorial_msg").stdout
    assert type_name == "ros_tutorials_interfaces/msg/MsgTutorial\n"


def test_interface_list_loads_no_rclpy():
    """`ros2 interface list` reads the ament index only."""
    modules, result = loaded("ros2cmd.entry:main", "interface", "list")
    assert result.returncode == 0 and "    std_msgs/msg/String\n" in result.stdout
    assert modules == [], f"`ros2 interface list` loaded {modules}"


def _subparsers(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    return {}


@pytest.mark.parametrize("verb", sorted(cli.VERB_MODULES))
def test_a_verbs_own_parser_is_the_whole_ones(verb):
    """`ros2 VERB ...` builds VERB's parser alone: its help, and each sub-verb's, is the one
    the whole parser (`ros2 -h`, TAB completion) has."""
    whole = _subparsers(cli.build_parser())[verb]
    own = _subparsers(cli.build_parser(verb))[verb]
    assert own.format_help() == whole.format_help()
    whole_commands, own_commands = _subparsers(whole), _subparsers(own)
    assert list(own_commands) == list(whole_commands)
    for name, command in whole_commands.items():
        assert own_commands[name].format_help() == command.format_help(), name


def test_ros2_help_is_the_whole_parsers_and_loads_no_verb():
    """`ros2 -h` prints the verbs' lines without loading their modules: the same help as the
    whole parser's, and none of the verbs' modules in the process."""
    assert cli.help_parser().format_help() == cli.build_parser().format_help()
    probe = (
        "import sys\nfrom ros2cmd.entry import main\ntry:\n    main(['-h'])\n"
        "except SystemExit:\n    pass\n"
        "print(sorted(m for m in sys.modules if m in set(sys.argv[1:])))"
    )
    modules = sorted(set(cli.VERB_MODULES.values()))
    result = subprocess.run(
        [sys.executable, "-c", probe, *modules],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
        stdin=subprocess.DEVNULL,
    )
    assert result.returncode == 0, result.stderr
    assert "Call `ros2 <command> -h` for more detailed usage." in result.stdout
    assert result.stdout.strip().splitlines()[-1] == "[]", result.stdout
