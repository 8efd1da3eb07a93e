"""`ros2` itself: its help lists ros2cli's verbs, `ros2` or `ros2 VERB` alone print help as
ros2cli does, and a verb it does not have is a usage error naming the ones it has."""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
from collections.abc import Iterator

import pytest
from helpers import run

from ros2cmd import cli
from ros_tutorials_common.cli import JazzyHelpFormatter


def test_ros2_help_lists_the_verbs_of_ros2cli():
    result = run("ros2", "-h")
    assert result.returncode == 0 and result.stdout.startswith("usage: ros2 ")
    assert "ros2 is an extensible command-line tool for ROS 2." in result.stdout
    for verb in ("action", "bag", "interface", "launch", "node", "param", "run", "service"):
        assert f"\n    {verb} " in result.stdout or f"\n    {verb}\n" in result.stdout, verb
    assert "Call `ros2 <command> -h` for more detailed usage." in result.stdout


def test_ros2_or_a_verb_alone_prints_its_help_and_ends_well():
    alone = run("ros2")
    assert alone.returncode == 0 and alone.stdout == run("ros2", "-h").stdout
    topic = run("ros2", "topic")
    assert topic.returncode == 0 and topic.stdout.startswith("usage: ros2 topic")
    assert "echo" in topic.stdout and topic.stderr == ""


def test_an_unknown_verb_is_a_usage_error_naming_the_verbs():
    result = run("ros2", "topics", "list")
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert "invalid choice: 'topics'" in result.stderr and "'topic'" in result.stderr


@pytest.mark.parametrize(
    ("value", "problem"),
    [
        ("abc", "'abc' is not a whole number in ASCII digits"),
        ("300", "'300' is above 232, the largest domain id Fast DDS can use"),
    ],
)
@pytest.mark.parametrize(
    "command",
    [("ros2", "topic", "list"), ("ros2", "daemon", "start"), ("rostopic", "list")],
    ids=" ".join,
)
def test_a_domain_id_dds_cannot_use_is_one_line(value, problem, command):
    # (Before: rcl's traceback, or Fast DDS's coloured lines and an empty list, exit 0.)
    result = run(*command, env={**os.environ, "ROS_DOMAIN_ID": value})
    assert result.returncode == 1 and result.stdout == ""
    assert result.stderr == (
        f"error: ROS_DOMAIN_ID={problem}: use one from 0 to 101 (every RMW takes those)\n"
    )


def test_ros2_launch_does_not_load_rclpy():
    """The launcher does not use rclpy: a process that has loaded it (and Fast DDS) can end
    with a segmentation fault after Ctrl-C (C++ code run at exit)."""
    code = (
        "import sys; from ros2cmd.entry import main; "
        "status = main(['launch', '--print', 'ros_tutorials_topic', 'union.launch.xml']); "
        "print('rclpy' in sys.modules); sys.exit(status)"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().splitlines()[-1] == "False"


def _parsers(parser: argparse.ArgumentParser) -> Iterator[argparse.ArgumentParser]:
    """The parser and every verb's and command's parser below it."""
    yield parser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in dict.fromkeys(action.choices.values()):  # `wtf` is doctor's parser too
                yield from _parsers(sub)


def test_help_is_laid_out_as_jazzy_prints_it_on_any_python(capsys):
    """ROS 2 Jazzy's help is Python 3.12's argparse layout (Ubuntu 24.04). Python 3.13's moves
    `ros2 -h`'s help column and names an option's value once; `ros2` keeps Jazzy's layout."""
    whole = cli.build_parser()
    for parser in _parsers(whole):
        assert issubclass(parser.formatter_class, JazzyHelpFormatter), parser.prog
    assert "\n    interface\n              Show information about ROS interfaces\n" in (
        cli.help_parser().format_help()
    )
    with pytest.raises(SystemExit):
        whole.parse_args(["bag", "info", "-h"])
    shown = capsys.readouterr().out
    assert "\n  -s {mcap,sqlite3}, --storage {mcap,sqlite3}\n" in shown, shown
