"""`ament_copyright [PATH ...]`: every source file below PATHS has a copyright notice and a
licence header, or one line says which it lacks (status 1).

The files judged are those ROS 2 Jazzy's ament_copyright judges: below a folder, the files
of its extensions, leaving out folders whose name starts with `.` or `_`, folders holding an
AMENT_IGNORE, and the `setup.py` beside a `package.xml` (a package's own setup.py carries no
header); an empty file is counted ("file empty" with --verbose) and is no error."""

from __future__ import annotations

import argparse
import os
import re
import sys
from collections.abc import Iterator, Sequence
from itertools import islice
from pathlib import Path

# The files a ROS package's code is in, as ament's linters take them.
SOURCE_SUFFIXES = {".py", ".c", ".cc", ".cpp", ".cxx", ".h", ".hh", ".hpp", ".hxx", ".cmake"}
SOURCE_NAMES = {"CMakeLists.txt"}
HEADER_LINES = 40  # a header is at the top of a file
NOTICE = re.compile(r"\bcopyright\b(\s*\(c\))?\s*\d{4}", re.I)
# A sentence of each licence header ros2 pkg create offers (ros2cmd/licenses/).
LICENSES = {
    "Apache-2.0": "Licensed under the Apache License, Version 2.0",
    "BSD": "Redistribution and use in source and binary forms",
    "MIT": "Permission is hereby granted, free of charge",
    "MIT-0": "Permission is hereby granted, free of charge",
    "BSL-1.0": "Boost Software License",
    "GPL-3.0-only": "GNU General Public License",
    "LGPL-3.0-only": "GNU Lesser General Public License",
}
SPDX = re.compile(r"SPDX-License-Identifier:\s*\S+")


def source_files(paths: Sequence[str], excluded: set[Path]) -> Iterator[Path]:
    """The source files named or below PATHS, each once, in order (the module's rule)."""
    seen: set[Path] = set()
    for path in map(Path, paths):
        if path.is_file():
            found = [path]
        else:
            found = []
            for folder, folders, files in os.walk(path):
                if "AMENT_IGNORE" in folders + files:
                    folders[:] = []
                    continue
                folders[:] = sorted(name for name in folders if name[0] not in "._")
                package_level = "package.xml" in files
                found += [
                    Path(folder, name)
                    for name in sorted(files)
                    if not (package_level and name == "setup.py")
                ]
        for file in found:
            wanted = file.suffix in SOURCE_SUFFIXES or file.name in SOURCE_NAMES
            if wanted and file.resolve() not in seen and file.resolve() not in excluded:
                seen.add(file.resolve())
                yield file


def is_empty(file: Path) -> bool:
    """Whether FILE has no content at all (an empty __init__.py)."""
    try:
        return file.stat().st_size == 0
    except OSError:
        return False


def problems(file: Path) -> list[str]:
    """What FILE's header lacks: a copyright notice, a licence."""
    try:
        with file.open(encoding="utf-8", errors="replace") as text:
            header = "".join(islice(text, HEADER_LINES))
    except OSError as error:
        return [f"cannot be read ({error.strerror})"]
    header = " ".join(re.sub(r"^\s*(#|//|/?\*+/?)", "", line) for line in header.splitlines())
    header = " ".join(header.split())
    found = []
    if not NOTICE.search(header):
        found.append("could not find copyright notice")
    if not (SPDX.search(header) or any(words in header for words in LICENSES.values())):
        found.append("could not find a license header")
    return found


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="ament_copyright", description="Check source files for copyright and license."
    )
    parser.add_argument("paths", nargs="*", default=[os.curdir], help="files or folders")
    parser.add_argument("--exclude", nargs="*", default=[], help="files to leave out")
    parser.add_argument("--verbose", action="store_true", help="name every file checked")
    args = parser.parse_args(argv)
    excluded = {Path(path).resolve() for path in args.exclude}
    checked = errors = 0
    for file in source_files(args.paths, excluded):
        checked += 1
        if is_empty(file):
            if args.verbose:
                print(f"{file}: file empty")
            continue
        found = problems(file)
        errors += len(found)
        for problem in found:
            print(f"{file}: {problem}")
        if args.verbose and not found:
            print(f"{file}: copyright and license found")
    if errors:
        print(f"{errors} errors, checked {checked} files")
        return 1
    print(f"No problems found, checked {checked} files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
