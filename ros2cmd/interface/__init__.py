"""`ros2 interface ...`: the message, service and action types installed (ROS 2's ros2interface).

    ros2 interface list [-m|-s|-a]          Messages: / Services: / Actions:, types indented
    ros2 interface show geometry_msgs/msg/Twist [--all-comments | --no-comments]
    ros2 interface package turtlesim        ros2 interface packages [-m|-s|-a]
    ros2 interface proto geometry_msgs/msg/Twist     the YAML a `topic pub` takes, quoted

These commands need no running graph: they read the ament resource index and the
definition files each interface package installs under share/<package>/.
`show` prints the file as it is, and after each field of a message type that type's
definition, indented by a tab, without its comments (unless --all-comments): what a
learner can set. Which lines count as comments is decided as rosidl's parser does it,
so the output is ros2interface's line for line (quirks included: a lone `#` or an indented
comment is not a comment to it, and stays).
"""

from __future__ import annotations

import argparse

from ros2cmd.interface.verb import list as list_verb
from ros2cmd.interface.verb import package, packages, proto, show
from ros2cmd.sub_verbs import VERB_HELP, add_sub_verbs

# `ros2 interface -h` lists them in this order.
SUB_VERBS = {
    "list": list_verb,
    "package": package,
    "packages": packages,
    "proto": proto,
    "show": show,
}


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("interface", help=VERB_HELP["interface"])
    sub = parser.add_subparsers(dest="command", metavar="Commands", required=True)
    add_sub_verbs(sub, SUB_VERBS, offline=True)
