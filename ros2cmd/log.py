"""`rqt_logger_level` and `roslaunch-logs`: a node's logger level, the launch log folder.

A running node's logger level is shown and changed through ROS 2 Jazzy's logger services,
``<node>/get_logger_levels`` and ``<node>/set_logger_levels`` (rcl_interfaces), which a node
serves when created with ``Node(..., enable_logger_service=True)``; every node of this
project's toolkit is, and the lessons whose level the pages change (the topic lesson's publisher,
seed 004's talker). The node's logger is named after it: ``/ns1/topic_publisher`` logs as
``ns1.topic_publisher``.

    rqt_logger_level                              every node: its level, or why it cannot be set
    rqt_logger_level /ns1/topic_publisher         one node's level
    rqt_logger_level /ns1/topic_publisher debug   change it; the node logs DEBUG lines now
    roslaunch-logs                                the latest launch's log folder
"""

from __future__ import annotations

import argparse
import os
import re
from pathlib import Path

from rcl_interfaces.msg import LoggerLevel
from rcl_interfaces.srv import GetLoggerLevels, SetLoggerLevels

from ros2cmd import completion
from ros2cmd.console import LEVELS, logger_name
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph

LEVEL_NAMES = {LoggerLevel.LOG_LEVEL_UNKNOWN: "UNSET", **{v: k.upper() for k, v in LEVELS.items()}}
GET, SET = "get_logger_levels", "set_logger_levels"


def _service(graph: Graph, node: str, which: str) -> str:
    """The node's logger service, or a clear error if the node does not serve it."""
    full_name = graph.wait_for_node(node)
    name = f"{full_name}/{which}"
    graph.settle()
    if name not in graph.service_types():
        raise ToolError(
            f"node '{full_name}' does not serve {name}: it was created without "
            "enable_logger_service=True, so its logger level cannot be changed from outside"
        )
    return name


# What is asked of a node's logger services and what its answers say, for the command
# below and for rqt's page (ros_tutorials_web/rqt.py), which calls the services its own way.


def get_request(node: str) -> GetLoggerLevels.Request:
    return GetLoggerLevels.Request(names=[logger_name(node)])


def level_in(response: GetLoggerLevels.Response) -> str:
    """The level a get_logger_levels answer gives: DEBUG, INFO, ..., or UNSET."""
    level = response.levels[0].level if response.levels else LoggerLevel.LOG_LEVEL_UNKNOWN
    return LEVEL_NAMES.get(level, str(level))


def set_request(node: str, level: str) -> SetLoggerLevels.Request:
    """Set the node's logger to ``level`` (a key of LEVELS: debug, info, ...)."""
    return SetLoggerLevels.Request(
        levels=[LoggerLevel(name=logger_name(node), level=LEVELS[level])]
    )


def refusal(node: str, level: str, response: SetLoggerLevels.Response) -> str | None:
    """Why a set_logger_levels answer did not set ``level`` (None: it did)."""
    result = response.results[0] if response.results else None
    if result is not None and result.successful:
        return None
    reason = result.reason if result is not None else "no answer for the logger"
    return f"'{node}' refused logger level {level.upper()}: {reason}"


def get_level(graph: Graph, node: str) -> str:
    """The node's logger level: DEBUG, INFO, ..., or UNSET (then its default, INFO, applies)."""
    client = graph.node.create_client(GetLoggerLevels, _service(graph, node, GET))
    response = graph.call(client, get_request(node), f"cannot get the logger level of '{node}'")
    return level_in(response)


def set_level(graph: Graph, node: str, level: str) -> None:
    client = graph.node.create_client(SetLoggerLevels, _service(graph, node, SET))
    request = set_request(node, level)
    response = graph.call(client, request, f"cannot set the logger level of '{node}'")
    refused = refusal(node, level, response)
    if refused is not None:
        raise ToolError(refused)


def level_command(graph: Graph, node: str | None, level: str | None) -> None:
    if node is None:
        graph.settle()
        services = graph.service_types()
        nodes = graph.node_names()
        if not nodes:
            raise ToolError("no running node (rqt_logger_level lists the running nodes)")
        for full_name in nodes:
            if f"{full_name}/{GET}" in services:
                print(f"{full_name}: {_described(get_level(graph, full_name))}")
            else:
                print(
                    f"{full_name}: cannot be set: it serves no {full_name}/{GET} (created "
                    "without enable_logger_service=True)"
                )
        return
    if level is not None:
        set_level(graph, node, level)
    full_name = "/" + node.strip("/")
    print(f"{full_name}: {_described(get_level(graph, full_name))}")


def _described(level: str) -> str:
    if level == "UNSET":
        return "UNSET (the default applies: INFO, unless started with --log-level)"
    return level


# A launch's folder, named as ros2 launch names it (launcher/supervise.py), or as this
# launcher named it before (launch_<date>_<pid>).
LAUNCH_FOLDER = re.compile(r"\d{4}(-\d\d){5}-\d{6}-.+-\d+|launch_.+")


def latest_launch_folder(base: Path | None = None) -> Path:
    """The newest folder of a launch's logs (<date>-<host>-<pid>, see launcher/supervise.py)."""
    if base is None:
        base = Path(os.environ.get("ROS_LOG_DIR") or Path.home() / ".ros" / "log")
    try:
        folders = [p for p in base.iterdir() if p.is_dir() and LAUNCH_FOLDER.fullmatch(p.name)]
    except OSError:
        folders = []
    if not folders:
        raise ToolError(f"no launch logs in {base} (a launch writes <date>-<host>-<pid> there)")
    return max(folders, key=lambda p: (p.stat().st_mtime, p.name))


def add_level_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", nargs="?", help="e.g. /ns1/topic_publisher (default: all nodes)")
    completion.attach(parser, node=completion.node_names)
    parser.add_argument("level", nargs="?", type=str.lower, choices=list(LEVELS))
