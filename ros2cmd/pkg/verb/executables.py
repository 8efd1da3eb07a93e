"""`ros2 pkg executables [PACKAGE] [--full-path]`: `turtlesim draw_square` ..., one a line."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.pkg.api import executables
from ros_tutorials_common import ament

HELP = "Output a list of package specific executables"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("package_name", nargs="?", help="The package name")
    completion.attach(parser, package_name=completion.package_names)
    parser.add_argument(
        "--full-path", action="store_true", help="Show full path of each executable"
    )


def main(_graph: None, args: argparse.Namespace) -> None:
    name = args.package_name
    for package in [name] if name else sorted(ament.packages()):
        for executable, path in executables(package).items():
            print(path if args.full_path else f"{package} {executable}")
