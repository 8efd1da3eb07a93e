"""`ros2 interface package PKG [-m|-s|-a]`: the package's types."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.interface.api import KINDS, add_kind_flags, chosen_kinds, list_types

HELP = "Output a list of available interface types within one package"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_kind_flags(parser, "Print out")
    parser.add_argument("package", help="Name of the ROS package (e.g. 'example_interfaces')")
    completion.attach(parser, package=completion.interface_packages)


def main(_graph: object, args: argparse.Namespace) -> None:
    package_command(args.package, args.kinds and chosen_kinds(args))


def package_command(package: str, kinds: tuple[str, ...] | None) -> None:
    """`ros2 interface package PKG`: its types, sorted (ros2interface's order is a set's),
    or kind by kind as -m/-s/-a are given."""
    names = list_types(KINDS, package, sort=True) if kinds is None else []
    for kind in kinds or ():
        names += list_types((kind,), package, sort=True)
    if names:
        print(*names, sep="\n")
