"""`ros2 service`: list, type, find, info, call and echo, as ros2service (ROS 2 Jazzy) has
them: `list -t` gives ``/clear [std_srvs/srv/Empty]``, `info` its ``Type:``, ``Clients count:``
and ``Services count:`` lines.

One module per sub-verb in verb/ (its options beside its code), what they share in api.py;
ROS 1's rosservice (ros1/rosservice.py) uses them too.
"""

from __future__ import annotations

import argparse

from ros2cmd.service.verb import call, echo, find, info
from ros2cmd.service.verb import list as list_verb
from ros2cmd.service.verb import type as type_verb
from ros2cmd.sub_verbs import VERB_HELP, add_sub_verbs

# `ros2 service -h` lists them in this order.
SUB_VERBS = {
    "list": list_verb,
    "type": type_verb,
    "find": find,
    "info": info,
    "call": call,
    "echo": echo,
}


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("service", help=VERB_HELP["service"])
    # As ros2cli: before the sub-command too (`ros2 service --include-hidden-services list`).
    parser.add_argument(
        "--include-hidden-services",
        dest="hidden_before",
        action="store_true",
        help="Consider hidden services as well",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    add_sub_verbs(sub, SUB_VERBS, parents=[common])
