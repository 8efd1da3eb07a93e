"""A claim of docs/dev/limits.md about the pinned Fast DDS wheel, checked.

The docs say that a process can hang for good at its end: Fast DDS's
``DomainParticipant::set_listener(nullptr)`` (rmw_fastrtps calls it when the last node is
destroyed) never returns if a discovery callback was running when it was called.
tools/fastdds_check builds a 60-line C++ program against this environment's wheel that makes
exactly that happen. When a new wheel fixes it, this test fails: then the docs, the benchmark's
note and the issue's note must change.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.skipif(
    shutil.which("g++") is None and shutil.which("c++") is None, reason="no C++ compiler"
)
def test_the_wheel_still_deadlocks_in_set_listener(own_domain: int) -> None:
    # A domain of its own: its two participants announce no ROS nodes, and the tools of other
    # tests wait to hear which nodes each participant of their domain holds.
    ran = subprocess.run(
        [sys.executable, str(ROOT / "tools" / "fastdds_check" / "run.py"), str(own_domain)],
        capture_output=True,
        text=True,
        timeout=180,
    )
    report = (ran.stdout + ran.stderr).strip()
    assert ran.returncode != 0, (
        f"Fast DDS's set_listener no longer deadlocks ({report}): update docs/dev/limits.md "
        "('Not fixable here'), docs/dev/performance.md and benchmarks/launch.py's note"
    )
    assert ran.returncode == 3, report
    assert report.startswith("deadlock: set_listener(nullptr) had not returned"), report
