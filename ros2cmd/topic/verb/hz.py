"""`ros2 topic hz TOPIC`: the rate over the last --window messages, about once a second (once a
second of messages has arrived since the last report)."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.graph import Graph, until_stopped
from ros2cmd.topic.api import (
    HZ_WINDOW,
    HzMeter,
    add_graph_options,
    filter_expression,
    subscribe_when_known,
)
from ros_tutorials_common.cli import positive_int

HELP = "Print the average publishing rate to screen"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic_name", help="Name of the ROS topic to listen to (e.g. '/chatter')")
    completion.attach(parser, topic_name=completion.topic_names)
    parser.add_argument(
        "--window",
        "-w",
        dest="window_size",
        type=positive_int,
        default=HZ_WINDOW,
        metavar="WINDOW",
        help=f"window size, in # of messages, for calculating rate (default: {HZ_WINDOW})",
    )
    parser.add_argument(
        "--filter",
        dest="filter_expr",
        metavar="EXPR",
        help="only measure messages matching the specified Python expression",
    )
    add_graph_options(parser)


def main(graph: Graph, args: argparse.Namespace) -> None:
    with until_stopped():
        meter = HzMeter(args.window_size)
        subscribe_when_known(graph, args.topic_name, meter.add, raw=args.filter_expr is None)
        meter.keep = filter_expression(args.filter_expr)
        while True:
            graph.spin_once(0.1)
            report = meter.report()
            if report:
                print(report, flush=True)
