"""`rospack find PKG` and `rospack list`: where this project's packages are (for roscd, rosed).

    rospack find ros_tutorials_topic        /.../ros_tutorials_topic
    cd $(rospack find ros_tutorials_topic)/launch     (what `roscd` did)

Tutorial packages are the folders of their Python code; interface packages are their source
folders in interfaces/ (where a learner adds a .msg), or their installed share/ folder.
A seed's package name (`my_package`) is found when it stands for one package here.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence
from pathlib import Path

from launcher import packages

SOURCE_INTERFACES = Path(packages.__file__).resolve().parent.parent / "interfaces"


def all_packages() -> dict[str, Path]:
    """Every package by name: interface sources in interfaces/, tutorial packages, then the
    interface packages installed in share/ (std_msgs, ...)."""
    found = {path.parent.name: path.parent for path in SOURCE_INTERFACES.glob("*/package.xml")}
    for name, path in packages.package_dirs().items():
        found.setdefault(name, path)
    prefixes = [p for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    for prefix in [*prefixes, sys.prefix]:
        index = Path(prefix) / "share" / "ament_index" / "resource_index" / "rosidl_interfaces"
        if index.is_dir():
            for entry in index.iterdir():
                found.setdefault(entry.name, Path(prefix) / "share" / entry.name)
    return dict(sorted(found.items()))


def find(name: str) -> Path:
    known = all_packages()
    if name in known:
        return known[name]
    targets = packages.resolve_package(name)
    if len(targets) == 1:
        return known[targets[0]]
    if targets:
        raise LookupError(f"{name} (a seed's package) stands for {', '.join(targets)}; name one")
    raise LookupError(f"unknown package {name!r}; known packages: {', '.join(known)}")


def rospack(argv: Sequence[str] | None = None) -> int:
    """The `rospack` command (console script): find and list."""
    parser = argparse.ArgumentParser(prog="rospack", description=__doc__.split("\n")[0])
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    commands.add_parser("find", help="print the folder of a package").add_argument("package")
    commands.add_parser("list", help="print every package and its folder")
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
