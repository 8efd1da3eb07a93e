"""`ros2 bag record|play|info|reindex`: ROS 2 Jazzy's ros2bag verbs, their options and their checks.

The options are ros2bag's (ros2bag/verb/record.py, play.py, info.py, branch jazzy), with its
defaults and its `[ERROR] [ros2bag]: ...` and `[WARN] [ros2bag]: ...` lines. An option this
project does not implement (compression, snapshots, sim time, QoS override files, splitting)
is refused with one line saying so, rather than silently ignored. One module per verb in
verb/, what they share in api.py; the work itself is ros2cmd/bag/'s record.py, play.py,
info.py.
"""

from __future__ import annotations

import argparse

from ros2cmd.bag.options import add_reindex, timeout_option
from ros2cmd.bag.ros2.verb import info, play, record
from ros2cmd.sub_verbs import VERB_HELP


def register(verbs: argparse._SubParsersAction, _common: argparse.ArgumentParser) -> None:
    """`ros2 bag info|play|record|reindex`."""
    parser = verbs.add_parser("bag", help=VERB_HELP["bag"])
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    info.add_arguments(sub.add_parser("info", help=info.HELP))
    play.add_arguments(sub.add_parser("play", parents=[timeout_option()], help=play.HELP))
    record.add_arguments(sub.add_parser("record", help=record.HELP))
    add_reindex(sub)
