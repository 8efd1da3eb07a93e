"""`ros2 pkg`: the packages of the ament index, and a new package (ROS 2's ros2pkg).

    ros2 pkg list                          every package of the ament index, sorted
    ros2 pkg prefix turtlesim [--share]    its install prefix (or share/turtlesim)
    ros2 pkg executables turtlesim         `turtlesim draw_square` ... one a line, sorted
    ros2 pkg xml turtlesim [-t version]    its package.xml (or one tag's text)
    ros2 pkg create --build-type ament_python --license Apache-2.0 --node-name my_node my_package

One module per sub-verb in verb/ (its options beside its code), what they share in api.py,
the files `create` writes in templates.py.
"""

from __future__ import annotations

import argparse

from ros2cmd.pkg.verb import create, executables, prefix, xml
from ros2cmd.pkg.verb import list as list_verb
from ros2cmd.sub_verbs import VERB_HELP, add_sub_verbs

# `ros2 pkg -h` lists them in this order.
SUB_VERBS = {
    "create": create,
    "executables": executables,
    "list": list_verb,
    "prefix": prefix,
    "xml": xml,
}


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("pkg", help=VERB_HELP["pkg"])
    sub = parser.add_subparsers(dest="command", metavar="Commands", required=True)
    add_sub_verbs(sub, SUB_VERBS, offline=True)
