"""`ros2 topic`: list, echo, pub, hz, bw, delay, info, type and find, as ros2topic (ROS 2
Jazzy) has them: their options and their output line for line.

One module per sub-verb in verb/ (its options beside its code), what they share in api.py;
ROS 1's rostopic (ros1/rostopic.py) uses api.py too.
"""

from __future__ import annotations

import argparse

from ros2cmd.sub_verbs import VERB_HELP, add_sub_verbs
from ros2cmd.topic.verb import bw, delay, echo, find, hz, info, pub
from ros2cmd.topic.verb import list as list_verb
from ros2cmd.topic.verb import type as type_verb
from ros_tutorials_common.cli import JazzyRawDescriptionHelpFormatter

# `ros2 topic -h` lists them in this order.
SUB_VERBS = {
    "bw": bw,
    "delay": delay,
    "echo": echo,
    "find": find,
    "hz": hz,
    "info": info,
    "list": list_verb,
    "pub": pub,
    "type": type_verb,
}


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    """`ros2 topic` and its sub-verbs, as ros2topic has them."""
    parser = verbs.add_parser(
        "topic",
        help=VERB_HELP["topic"],
        description=VERB_HELP["topic"],
        formatter_class=JazzyRawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "--include-hidden-topics", action="store_true", help="Consider hidden topics as well"
    )
    width = max(len(name) for name in SUB_VERBS)
    sub = parser.add_subparsers(
        dest="command",
        title="Commands",
        description="".join(
            f"{name.ljust(width)}  {module.HELP}\n" for name, module in SUB_VERBS.items()
        ),
        metavar="Call `ros2 topic <command> -h` for more detailed usage.",
    )
    parser.set_defaults(offline=True, run=lambda _graph, _args: parser.print_help())
    add_sub_verbs(sub, SUB_VERBS, listed_in_description=True)
