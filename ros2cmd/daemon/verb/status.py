"""`ros2 daemon status`: whether the daemon is running."""

from __future__ import annotations

import argparse
from typing import Any

from ros2cmd.daemon import client

HELP = "Output the status of the daemon"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pass


def main(_graph: Any, _args: argparse.Namespace) -> None:
    print("The daemon is running" if client.is_running() else "The daemon is not running")
