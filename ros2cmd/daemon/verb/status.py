"""`ros2 daemon status`: whether the daemon is running."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from ros2cmd.daemon import client

HELP = "Output the status of the daemon"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pass


def main(_graph: Any, _args: argparse.Namespace) -> None:
    if client.is_running():
        print("The daemon is running")
        return
    print("The daemon is not running")
    holder = client.name_holder()
    if holder is not None:
        print(f"warning: {client.held_by_another_user(holder)}", file=sys.stderr)
