"""`ros2 pkg prefix PACKAGE [--share]`: its install prefix (or share/PACKAGE)."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.pkg.api import package_prefix
from ros_tutorials_common import ament, packages

HELP = "Output the prefix path of a package"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("package_name", help="The package name")
    completion.attach(parser, package_name=completion.package_names)
    parser.add_argument("--share", action="store_true", help="Show share directory for the package")


def main(_graph: None, args: argparse.Namespace) -> None:
    name, share = args.package_name, args.share
    if name in ament.packages():
        path = package_prefix(name)
        print(path / "share" / name if share else path)
        return
    try:  # a seed's name `ros2 run` takes (demo_nodes_cpp): the package it stands for
        print(packages.share_directory(name) if share else packages.prefix(name))
    except packages.UnknownPackage as error:
        known = packages.resolve_package(name)
        raise ToolError(str(error) if known else f"Package '{name}' not found") from None
