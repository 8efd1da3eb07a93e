"""`rospack find PKG` and `rospack list`: where the packages are (for roscd, rosed).

    rospack find ros_tutorials_topic        /.../ros_tutorials_topic
    cd $(rospack find ros_tutorials_topic)/launch     (what `roscd` did)

The packages are those of the ament index (AMENT_PREFIX_PATH, this environment by default).
As in ROS 1, a package of this workspace is found at its source folder, where a learner adds a
node or a .msg (the lessons' folders, interfaces/PKG), an installed one at share/PKG
(ros_tutorials_common/packages.py package_folder()). A seed's package name (`my_package`) is
found when it stands for one package here.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path

from ros2cmd import completion
from ros_tutorials_common import ament, packages
from ros_tutorials_common.shutdown import program_main


def all_packages() -> dict[str, Path]:
    """Every package of the ament index, by name, and its folder."""
    return {name: packages.package_folder(name) for name in ament.packages()}


def find(name: str) -> Path:
    return packages.package_folder(name)


@program_main
def rospack(argv: Sequence[str] | None = None) -> int:
    """The `rospack` command (console script): find and list."""
    parser = argparse.ArgumentParser(prog="rospack", description=__doc__.split("\n")[0])
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    commands.add_parser("find", help="print the folder of a package").add_argument("package")
    completion.attach(commands.choices["find"], package=completion.package_names)
    commands.add_parser("list", help="print every package and its folder")
    completion.answer(parser)  # the shell asking for TAB's completions: ends here
    options = parser.parse_args(sys.argv[1:] if argv is None else argv)
    if options.command == "list":
        for name, path in all_packages().items():
            print(name, path)
        return 0
    try:
        print(find(options.package))
    except LookupError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    return 0
