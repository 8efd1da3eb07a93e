"""`ros2 topic delay TOPIC`: how old header.stamp is when each message arrives, each second."""

from __future__ import annotations

import argparse
import math
from collections import deque
from typing import Any

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name, until_stopped
from ros2cmd.topic.api import (
    HZ_WINDOW,
    add_graph_options,
    every_second,
    single_type,
    subscribe_when_known,
)
from ros2cmd.typenames import full_type_name
from ros_tutorials_common.cli import positive_int

HELP = "Display delay of topic from timestamp in header"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="Topic name to calculate the delay for")
    completion.attach(parser, topic=completion.topic_names)
    parser.add_argument(
        "--window",
        "-w",
        type=positive_int,
        default=HZ_WINDOW,
        help=f"window size, in # of messages, for calculating rate (default: {HZ_WINDOW})",
    )
    add_graph_options(parser)


def main(graph: Graph, args: argparse.Namespace) -> None:
    from rclpy.time import Time

    with until_stopped():
        delays: deque[int] = deque(maxlen=args.window)  # ns
        new = [False]

        def on_message(msg: Any) -> None:
            now = graph.node.get_clock().now()
            delays.append((now - Time.from_msg(msg.header.stamp)).nanoseconds)
            new[0] = True

        topic = absolute_name(args.topic)
        msg_type = single_type(graph, topic, None)
        if "header" not in msg_type.get_fields_and_field_types():
            raise ToolError(f"msg does not have header: {full_type_name(msg_type)} has none")
        subscribe_when_known(graph, topic, on_message, raw=False)
        for _ in every_second(graph):
            if not delays:
                continue
            if not new[0]:
                print("no new messages", flush=True)
                continue
            new[0] = False
            n = len(delays)
            mean = sum(delays) / n
            std_dev = math.sqrt(sum((x - mean) ** 2 for x in delays) / n)
            print(
                f"average delay: {mean * 1e-9:.3f}\n\tmin: {min(delays) * 1e-9:.3f}s "
                f"max: {max(delays) * 1e-9:.3f}s std dev: {std_dev * 1e-9:.5f}s window: {n}",
                flush=True,
            )
