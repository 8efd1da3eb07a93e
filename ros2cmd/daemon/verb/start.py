"""`ros2 daemon start`: start the daemon if it isn't running."""

from __future__ import annotations

import argparse
from typing import Any

from ros2cmd.daemon import client

HELP = "Start the daemon if it isn't running"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pass


def main(_graph: Any, _args: argparse.Namespace) -> None:
    print("The daemon has been started" if client.start() else "The daemon is already running")
