"""`ros2 topic bw TOPIC`: bytes per second over the last --window messages, each second."""

from __future__ import annotations

import argparse
import time
from collections import deque

from ros2cmd import completion
from ros2cmd.graph import Graph, absolute_name, until_stopped
from ros2cmd.topic.api import add_graph_options, every_second, subscribe_when_known
from ros_tutorials_common.cli import positive_int

HELP = "Display bandwidth used by topic"
BW_WINDOW = 100  # messages, as ros2topic bw


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="Topic name to monitor for bandwidth utilization")
    completion.attach(parser, topic=completion.topic_names)
    parser.add_argument(
        "--window",
        "-w",
        type=positive_int,
        default=BW_WINDOW,
        metavar="WINDOW",
        help=f"maximum window size, in # of messages, for calculating rate (default: {BW_WINDOW})",
    )
    add_graph_options(parser)


def main(graph: Graph, args: argparse.Namespace) -> None:
    with until_stopped():
        arrivals: deque[tuple[int, int]] = deque(maxlen=args.window)  # (time ns, bytes)
        topic = absolute_name(args.topic)
        subscribe_when_known(
            graph, topic, lambda raw: arrivals.append((time.time_ns(), len(raw))), raw=True
        )
        print(f"Subscribed to [{topic}]", flush=True)
        for _ in every_second(graph):
            if len(arrivals) >= 2:
                print(_bandwidth(list(arrivals), time.time_ns()), flush=True)


def _bandwidth(arrivals: list[tuple[int, int]], now: int) -> str:
    sizes = [size for _, size in arrivals]
    total = sum(sizes)
    per_second = total / ((now - arrivals[0][0]) * 1e-9)
    figures = (per_second, total / len(sizes), min(sizes), max(sizes))
    if per_second < 1000:
        rate, mean, low, high = (f"{x:.0f} B" for x in figures)
    elif per_second < 1_000_000:
        rate, mean, low, high = (f"{x / 1000:.2f} KB" for x in figures)
    else:
        rate, mean, low, high = (f"{x / 1000 / 1000:.2f} MB" for x in figures)
    return (
        f"{rate}/s from {len(sizes)} messages\n\tMessage size mean: {mean} min: {low} max: {high}"
    )
