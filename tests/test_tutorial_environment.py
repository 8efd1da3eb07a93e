"""The official Jazzy tutorial "Configuring environment": after sourcing the environment
(here `source .venv/bin/activate`, there `source /opt/ros/jazzy/setup.bash`),
`printenv | grep -i ROS` shows the variables the page shows."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

PAGE = ["ROS_VERSION=2", "ROS_PYTHON_VERSION=3", "ROS_DISTRO=jazzy"]


def _bash(script: str) -> list[str]:
    activate = Path(sys.prefix) / "bin" / "activate"
    result = subprocess.run(
        ["bash", "-c", f"source {activate}\n{script}"],
        capture_output=True,
        text=True,
        timeout=30,
        env={"PATH": "/usr/bin:/bin", "HOME": str(Path.home())},
    )
    assert result.returncode == 0, result.stderr
    return result.stdout.splitlines()


def test_printenv_shows_what_the_page_shows_and_deactivate_takes_it_away():
    shown = _bash("printenv | grep -i ROS")
    assert [line for line in shown if line in PAGE] == PAGE
    assert not [line for line in _bash("deactivate\nprintenv") if line in PAGE]


def test_sourcing_twice_keeps_one_definition():
    assert _bash("source $VIRTUAL_ENV/bin/activate\nprintenv ROS_DISTRO") == ["jazzy"]
