"""The ROS 1 GUI tools the seeds use, in their spellings: rqt_graph, rqt_console,
rqt_logger_level, and roslaunch-logs (ROS 2 runs them as `ros2 run rqt_graph rqt_graph`, ...).

    rqt_graph                   a window where there is a display, else DOT on stdout
    rqt_console                 the live /rosout lines in the terminal
    rqt_logger_level [NODE [LEVEL]]   show or change a node's logger level
    roslaunch-logs              the latest launch's log folder
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence

from ros2cmd import completion, console, graph_view, log
from ros2cmd.cli import common_options, execute
from ros2cmd.graph import DEFAULT_TIMEOUT, Graph
from ros_tutorials_common.shutdown import program_main


def _parser(prog: str, description: str) -> argparse.ArgumentParser:
    return argparse.ArgumentParser(prog=prog, description=description, parents=[common_options()])


def _execute(args: argparse.Namespace, run, offline: bool = False) -> int:
    return execute(
        lambda graph: run(graph, args),
        offline=offline,
        timeout=getattr(args, "timeout", DEFAULT_TIMEOUT),
        spin_time=getattr(args, "spin_time", None),
    )


@program_main
def rqt_graph(argv: Sequence[str] | None = None) -> int:
    parser = _parser("rqt_graph", "The running graph: a window, or DOT/SVG/PNG")
    graph_view.add_arguments(parser)
    completion.answer(parser)  # the shell asking for TAB's completions: ends here
    args = parser.parse_args(argv)
    if not args.output and not args.window:
        if os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"):
            args.window = True
        else:
            print("no display: printing DOT (-o graph.svg writes a picture)", file=sys.stderr)
    return _execute(args, graph_view.run)


@program_main
def rqt_console(argv: Sequence[str] | None = None) -> int:
    parser = _parser("rqt_console", "The live /rosout log lines")
    console.add_arguments(parser)
    completion.answer(parser)
    return _execute(parser.parse_args(argv), console.run)


@program_main
def rqt_logger_level(argv: Sequence[str] | None = None) -> int:
    parser = _parser("rqt_logger_level", "Show or change node logger levels")
    log.add_level_arguments(parser)
    completion.answer(parser)
    args = parser.parse_args(argv)
    return _execute(args, lambda graph, a: log.level_command(graph, a.node, a.level))


def roslaunch_logs(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="roslaunch-logs", description="Print the folder of the latest launch's logs"
    )
    completion.answer(parser)
    args = parser.parse_args(argv)

    def run(_graph: Graph | None, _args: argparse.Namespace) -> None:
        print(log.latest_launch_folder())

    return _execute(args, run, offline=True)
