"""`ros2 pkg list`: every package of the ament index, sorted."""

from __future__ import annotations

import argparse

from ros_tutorials_common import ament

HELP = "Output a list of available packages"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """No options."""


def main(_graph: None, _args: argparse.Namespace) -> None:
    for name in sorted(ament.packages()):
        print(name)
