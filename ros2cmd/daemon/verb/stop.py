"""`ros2 daemon stop`: stop the daemon if it is running."""

from __future__ import annotations

import argparse
from typing import Any

from ros2cmd.daemon import client

HELP = "Stop the daemon if it is running"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pass


def main(_graph: Any, _args: argparse.Namespace) -> None:
    print("The daemon has been stopped" if client.stop() else "The daemon is not running")
