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
    # The template's own tests carry the Apache header; the learner's files do not yet.
    assert "setup.py: could not find copyright notice" in lines
    assert "my_package/my_node.py: could not find a license header" in lines
    assert not [line for line in lines if line.startswith("test/")]
    assert lines[-1] == "6 errors, checked 6 files"
    for name in ("setup.py", "my_package/__init__.py", "my_package/my_node.py"):
        path = package / name
        path.write_text(HEADER + path.read_text())
    result = check(package)
    assert result.returncode == 0, result.stdout
    assert result.stdout == "No problems found, checked 6 files\n"
