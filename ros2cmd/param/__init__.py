"""`ros2 param`: list, get, set, delete, describe, dump and load a node's parameters through
its parameter services, printed as ROS 2 Jazzy's ros2param prints them
(`Integer value is: 86`, `Set parameter successful`, the dump's `/node:` /
`  ros__parameters:` YAML).

One module per sub-verb in verb/ (its options beside its code), what they share in api.py;
ROS 1's rosparam (ros1/rosparam.py) uses api.py too.
"""

from __future__ import annotations

import argparse

from ros2cmd.param.verb import delete, describe, dump, get, load
from ros2cmd.param.verb import list as list_verb
from ros2cmd.param.verb import set as set_verb
from ros2cmd.sub_verbs import VERB_HELP, add_sub_verbs

# `ros2 param -h` lists them in this order.
SUB_VERBS = {
    "delete": delete,
    "describe": describe,
    "dump": dump,
    "get": get,
    "list": list_verb,
    "load": load,
    "set": set_verb,
}


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("param", help=VERB_HELP["param"])
    sub = parser.add_subparsers(dest="command", metavar="Commands", required=True)
    add_sub_verbs(sub, SUB_VERBS, parents=[common])
