"""`ros2 interface list [-m|-s|-a]`: Messages: / Services: / Actions:, types indented."""

from __future__ import annotations

import argparse

from ros2cmd.interface.api import KIND_TITLES, add_kind_flags, chosen_kinds, list_types

HELP = "List all interface types available"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_kind_flags(parser, "Print out")


def main(_graph: object, args: argparse.Namespace) -> None:
    list_command(chosen_kinds(args))


def list_command(kinds: tuple[str, ...]) -> None:
    for kind in kinds:
        print(f"{KIND_TITLES[kind]}:")
        for name in list_types((kind,), sort=True):
            print(f"    {name}")
