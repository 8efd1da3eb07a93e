"""This environment's ament_copyright (ament_copyright/), which the test_copyright.py of every
package `ros2 pkg create` makes imports: on such a package's files, as that test runs it once
its skip decorator is removed (`main(argv=['.', 'test'])` in the package's folder)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROS2 = Path(sys.prefix) / "bin" / "ros2"
AMENT_COPYRIGHT = Path(sys.prefix) / "bin" / "ament_copyright"
HEADER = (
    "# Copyright 2026 A Learner\n#\n"
    '# Licensed under the Apache License, Version 2.0 (the "License");\n'
)


def check(package: Path) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(AMENT_COPYRIGHT), ".", "test"],
        cwd=package,
        capture_output=True,
        text=True,
        timeout=60,
    )


def test_files_without_a_header_are_named_and_fail_until_they_have_one(tmp_path):
    subprocess.run(
        [
            str(ROS2),
            "pkg",
            "create",
            "--build-type",
            "ament_python",
            "--license",
            "Apache-2.0",
            "--node-name",
            "my_node",
            "my_package",
        ],
        cwd=tmp_path,
        check=True,
        capture_output=True,
        timeout=60,
    )
    package = tmp_path / "my_package"
    result = check(package)
    assert result.returncode == 1 and result.stderr == ""
    lines = result.stdout.splitlines()
    # The template's own tests carry the Apache header; the learner's node does not yet. As
    # Jazzy's ament_copyright: the setup.py beside package.xml is not judged, and the empty
    # __init__.py is counted but no error.
    assert lines == [
        "my_package/my_node.py: could not find copyright notice",
        "my_package/my_node.py: could not find a license header",
        "2 errors, checked 5 files",
    ]
    path = package / "my_package" / "my_node.py"
    path.write_text(HEADER + path.read_text())
    result = check(package)
    assert result.returncode == 0, result.stdout
    assert result.stdout == "No problems found, checked 5 files\n"
    verbose = subprocess.run(
        [str(AMENT_COPYRIGHT), "--verbose", ".", "test"],
        cwd=package,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert "my_package/__init__.py: file empty" in verbose.stdout.splitlines()


def test_folders_and_files_judged_as_jazzys_ament_copyright_judges_them(tmp_path):
    """A file named on the command line is judged, setup.py too; below a folder, `_` and `.`
    folders and AMENT_IGNORE'd ones are left out, and a setup.py not beside a package.xml is
    judged; a file of only a newline is not empty."""
    (tmp_path / "package.xml").write_text("<package/>\n")
    (tmp_path / "setup.py").write_text("print()\n")
    for folder in ("_private", ".hidden", "ignored", "tools"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "code.py").write_text("print()\n")
    (tmp_path / "ignored" / "AMENT_IGNORE").write_text("")
    (tmp_path / "tools" / "setup.py").write_text("print()\n")
    (tmp_path / "newline.py").write_text("\n")
    result = check(tmp_path)
    problems = {line.split(": ")[0] for line in result.stdout.splitlines()[:-1]}
    assert problems == {"tools/code.py", "tools/setup.py", "newline.py"}, result.stdout
    named = subprocess.run(
        [str(AMENT_COPYRIGHT), "setup.py"], cwd=tmp_path, capture_output=True, text=True, timeout=60
    )
    assert named.returncode == 1 and named.stdout.startswith("setup.py: could not find")
