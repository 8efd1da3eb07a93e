"""Run ros2/launch's own test suite (launch/test, launch_xml/test, launch_yaml/test) against
this project's ``launch``, ``launch_xml`` and ``launch_yaml``.

    .venv/bin/python tools/run_launch_upstream_tests.py /tmp/ros2launch [pytest options]

The checkout is ros2/launch at branch jazzy (``git clone -b jazzy
https://github.com/ros2/launch``); nothing of it is copied into the project. Its linters'
tests (copyright, flake8, mypy, pep257) check upstream's own sources and are left out.
Prints pytest's summary; the exit status is pytest's.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SUITES = ("launch/test", "launch_xml/test", "launch_yaml/test")
LINTERS = ("test_copyright.py", "test_flake8.py", "test_mypy.py", "test_pep257.py")


def main(argv: list[str]) -> int:
    if not argv or argv[0] in ("-h", "--help"):
        try:
            print(__doc__.strip(), flush=True)
        except BrokenPipeError:  # | head: the reader has what it wanted
            sys.stdout = None  # type: ignore[assignment]  (nothing left to flush at exit)
        return 0 if argv else 2
    checkout = Path(argv[0]).resolve()
    missing = [suite for suite in SUITES if not (checkout / suite).is_dir()]
    if missing:
        print(f"error: {checkout} is not a ros2/launch checkout (no {missing[0]})", file=sys.stderr)
        return 2
    env = dict(
        os.environ,
        PYTHONPATH=os.pathsep.join(
            [str(ROOT)] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
        ),
    )
    worst = 0
    for suite in SUITES:  # one pytest each: the suites repeat test file names
        ignores = [f"--ignore={checkout / suite / name}" for name in LINTERS]
        command = [
            sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "--import-mode=append",
            "--noconftest", "--continue-on-collection-errors", "--rootdir", str(checkout / suite),
            "-o", "addopts=", *ignores, str(checkout / suite), *argv[1:],
        ]  # fmt: skip
        print(f"== {suite}", flush=True)
        worst = max(worst, subprocess.call(command, cwd=checkout / suite, env=env))
    return worst


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
