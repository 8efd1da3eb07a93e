"""`ros2 action`: list, info, type and send_goal, as ros2action (ROS 2 Jazzy) has them.

One module per sub-verb in verb/ (its options beside its code), what they share in api.py;
goal.py waits on a goal without hanging and cancels it on Ctrl-C.
"""

from __future__ import annotations

import argparse

from ros2cmd.action.verb import info, send_goal
from ros2cmd.action.verb import list as list_verb
from ros2cmd.action.verb import type as type_verb
from ros2cmd.sub_verbs import VERB_HELP, add_sub_verbs

# `ros2 action -h` lists them in this order.
SUB_VERBS = {"info": info, "list": list_verb, "send_goal": send_goal, "type": type_verb}


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("action", help=VERB_HELP["action"])
    sub = parser.add_subparsers(dest="command", metavar="Commands", required=True)
    add_sub_verbs(sub, SUB_VERBS, parents=[common])
