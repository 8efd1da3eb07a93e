"""`rostopic list|echo|pub|hz|bw|info|type|find`: ROS 1's rostopic on `ros2 topic`'s code.

    rostopic pub /cmd_vel geometry_msgs/Twist -r 10 '{linear: {x: 1.0}}'    options anywhere
    rostopic echo /turtle1/pose/x                                          one field, by name

Each command runs ros2cmd/topic.py's function; see ros2cmd/ros1/tool.py for what all share.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence

from ros2cmd import topic
from ros2cmd.graph import Graph
from ros2cmd.ros1 import tool
from ros_tutorials_common.cli import positive_int, positive_rate
from ros_tutorials_common.ctrl_c import exits_130_on_ctrl_c


def rostopic_parser() -> argparse.ArgumentParser:
    parser, sub, common = tool.new_parser(
        "rostopic", "ROS 1's rostopic, on ROS 2 (see: ros2 topic)"
    )

    p = sub.add_parser("list", parents=[common], help="list topics")
    p.add_argument("-v", "--verbose", action="store_true", help="with types")
    p.set_defaults(run=lambda graph, a: topic.list_topics(graph, a.verbose))

    p = sub.add_parser("echo", parents=[common], help="print messages")
    p.add_argument("topic", help="a topic, or /topic/field for one field (/t/stamp/sec)")
    p.add_argument("-n", type=positive_int, help="print this many messages, then exit")
    p.set_defaults(run=lambda graph, a: topic.echo(graph, a.topic, count=a.n, field_in_name=True))

    p = sub.add_parser("pub", parents=[common], help="publish a message")
    p.add_argument("topic")
    p.add_argument("type")
    p.add_argument("values", nargs="*", help="a YAML mapping, or field values in order")
    group = p.add_mutually_exclusive_group()  # ROS 1 refused both too
    group.add_argument("-r", "--rate", type=positive_rate, help="publish at this rate until Ctrl-C")
    group.add_argument("-1", "--once", action="store_true", help="publish once, then exit")
    p.add_argument("-v", "--verbose", action="store_true", help="print each message (with -r)")
    p.set_defaults(run=_pub)

    for name, bandwidth in (("hz", False), ("bw", True)):
        p = sub.add_parser(name, parents=[common], help="")
        p.add_argument("topic")
        p.set_defaults(run=lambda graph, a, b=bandwidth: topic.hz(graph, a.topic, 10000, b))

    p = sub.add_parser("info", parents=[common], help="publishers etc.")
    p.add_argument("topic")
    p.set_defaults(run=lambda graph, a: topic.info(graph, a.topic, True))

    p = sub.add_parser("type", parents=[common], help="message type")
    p.add_argument("topic")
    p.set_defaults(run=lambda graph, a: topic.print_type(graph, a.topic))

    p = sub.add_parser("find", parents=[common], help="topics of a type")
    p.add_argument("type")
    p.set_defaults(run=lambda graph, a: topic.find(graph, a.type))
    return parser


def _pub(graph: Graph, args: argparse.Namespace) -> None:
    values = tool.values_from_args(args.values)
    if args.rate is not None:
        topic.pub(graph, args.topic, args.type, values, rate=args.rate, verbose=args.verbose)
    elif args.once:
        topic.pub(graph, args.topic, args.type, values, times=1)
    else:  # ROS 1's default: publish once, latched, until Ctrl-C
        topic.pub(graph, args.topic, args.type, values, rate=None, latch=True)


@exits_130_on_ctrl_c  # the console script's entry
def rostopic(argv: Sequence[str] | None = None) -> int:
    return tool.run(rostopic_parser(), argv)
