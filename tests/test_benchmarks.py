"""`make bench` keeps working: every benchmark group runs briefly (`python -m benchmarks
--smoke GROUP`: each step with the smallest counts and durations). Nothing is timed or
compared here (figures belong to benchmarks/); a step that raises, as the topic group's
import of a name the lesson no longer had did, fails its group's test."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from benchmarks.__main__ import GROUPS
from benchmarks.common import SMOKE_VARIABLE

SMOKE_TIMEOUT = 900.0  # s: a loaded 2-core machine; a colcon build is the longest step


@pytest.mark.parametrize("group", list(GROUPS))
def test_every_benchmark_group_runs(group: str) -> None:
    env = {key: value for key, value in os.environ.items() if key != SMOKE_VARIABLE}
    try:
        result = subprocess.run(
            [sys.executable, "-m", "benchmarks", "--smoke", group],
            capture_output=True,
            text=True,
            timeout=SMOKE_TIMEOUT,
            env=env,
        )
    except subprocess.TimeoutExpired:
        pytest.fail(f"the {group} benchmarks' smoke run did not end within {SMOKE_TIMEOUT:.0f} s")
    assert "(smoke run)" in result.stdout
    assert result.returncode == 0, f"{group}:\n{result.stdout[-4000:]}\n{result.stderr[-4000:]}"
    assert "FAILED" not in result.stdout
