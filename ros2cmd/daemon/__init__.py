"""`ros2 daemon start|stop|status`, as ros2cli has them; and the daemon they manage.

The daemon (server.py) is a background process holding one graph node that the lists ask
instead of discovering for themselves; client.py is what the lists, TAB completion and these
verbs ask it; protocol.py what both sides share (the socket's name, the peer's user).
One module per sub-verb in verb/.
"""

from __future__ import annotations

import argparse

from ros2cmd.daemon.verb import start, status, stop
from ros2cmd.sub_verbs import VERB_HELP, add_sub_verbs

# `ros2 daemon -h` lists them in this order.
SUB_VERBS = {"start": start, "status": status, "stop": stop}


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("daemon", help=VERB_HELP["daemon"])
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    add_sub_verbs(sub, SUB_VERBS, offline=True)
