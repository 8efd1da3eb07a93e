"""With CI=true, a browser or window test that would be skipped for want of a browser or a
display fails instead (conftest.py): on CI, `.ci/run` installs them, and a skipped browser
test would let the pages go untested. Shown on the window test, in a pytest of its own whose
PATH has no Xvfb."""

from __future__ import annotations

import os
import subprocess
import sys

from helpers import BIN, TIMEOUT

WINDOW_TEST = "tests/test_turtlesim_window.py"


def pytest_without_display(ci: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "PATH": str(BIN), "CI": ci}
    return subprocess.run(
        [sys.executable, "-m", "pytest", WINDOW_TEST, "-q", "-p", "no:cacheprovider", "-rs"],
        env=env,
        capture_output=True,
        text=True,
        timeout=TIMEOUT * 4,
        cwd=BIN.parents[1],
    )


def test_a_skip_for_want_of_a_display_fails_on_ci() -> None:
    result = pytest_without_display("true")
    assert result.returncode == 1, result.stdout
    assert "CI=true, and this test would be skipped: needs a browser or display" in result.stdout


def test_elsewhere_it_is_a_skip_with_the_reason() -> None:
    result = pytest_without_display("")
    assert result.returncode == 0, result.stdout
    assert "1 skipped" in result.stdout
    assert "needs a browser or display: Xvfb" in result.stdout
