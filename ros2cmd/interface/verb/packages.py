"""`ros2 interface packages [-m|-s|-a]`: the packages that provide interfaces."""

from __future__ import annotations

import argparse

from ros2cmd.interface.api import KINDS, add_kind_flags, chosen_kinds, packages

HELP = "Output a list of packages that provide interfaces"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_kind_flags(parser, "List")


def main(_graph: object, args: argparse.Namespace) -> None:
    print(*packages(_packages_kind(args)), sep="\n")


def _packages_kind(args: argparse.Namespace) -> tuple[str, ...]:
    """`packages -m -s` lists the message packages: ros2interface takes the first flag only."""
    return chosen_kinds(args)[:1] if args.kinds else KINDS
