"""Set-up: a fresh clone to ready (make setup), then a second `make test` that rebuilds nothing."""

from __future__ import annotations

import subprocess
import tempfile
import time
from pathlib import Path

from benchmarks.common import SMOKE, Row

ROOT = Path(__file__).resolve().parent.parent


def _timed(args: list[str], cwd: Path, check: bool = True) -> tuple[float, int]:
    start = time.monotonic()
    done = subprocess.run(
        args, cwd=cwd, check=check, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    return time.monotonic() - start, done.returncode


def setup_times() -> list[Row]:
    with tempfile.TemporaryDirectory() as tmp:
        clone = Path(tmp) / "clone"
        subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True)
        if SMOKE:  # the set-up's recipe as make would run it, not run (minutes, and a venv)
            dry, _ = _timed(["make", "-n", "setup"], clone)
            return [Row("make -n setup in a fresh clone (smoke run)", f"{dry:.2f} s")]
        fresh, _ = _timed(["make", "setup"], clone)
        noop, _ = _timed(["make", "setup"], clone)
        up_to_date = subprocess.run(["make", "-q", "setup"], cwd=clone).returncode == 0
        # A failing test must not cost the set-up figures: the time is reported with the exit.
        second_test, test_exit = _timed(["make", "test"], clone, check=False)
    return [
        Row("fresh clone to ready (make setup; pip cache warm)", f"{fresh:.0f} s"),
        Row(
            "make setup again, nothing changed",
            f"{noop:.2f} s",
            "",
            None,
            "make -q: up to date",
            up_to_date,
        ),
        Row(
            "make test after set-up (lint + whole suite, no rebuild)",
            f"{second_test:.0f} s" + (f" (FAILED, exit {test_exit})" if test_exit else ""),
            f"{noop:.2f} s of it is the set-up check",
            None,
            "passes",
            test_exit == 0,
        ),
    ]
