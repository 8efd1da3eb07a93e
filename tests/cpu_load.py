"""`pytest --cpu-load=auto`: run the tests with every core kept busy, to bring out races.

Shutdown and start-up races (a signal arriving between two steps that should be one, a
callback running into a destroyed handle) hide on a quiet machine and show when the
processes under test are descheduled at the wrong moment. This plugin starts N busy
processes before the first test and stops them after the last, so that such a run is
one command (`make test-load`).

The busy processes run at the same priority as the tests unless `--cpu-load-nice` says
otherwise (niced ones barely slow anything down: the scheduler gives them what the tests
leave). They are bounded three ways: pytest stops them when the session ends, also after
Ctrl-C or a failure; each stops itself after `--cpu-load-limit` seconds; and each stops
within a fraction of a second when pytest is gone (killed with SIGKILL, say).
"""

from __future__ import annotations

import os
import resource
import signal
import subprocess
import sys
import time

import pytest

# The busy loop: pure interpreter work, checking now and then whether it should stop.
WORKER = """
import os, sys, time
parent, end = int(sys.argv[1]), time.monotonic() + float(sys.argv[2])
os.nice(int(sys.argv[3]))
while os.getppid() == parent and time.monotonic() < end:
    for _ in range(20000):
        pass
"""
DEFAULT_LIMIT = 3600.0


def _count(text: str) -> int:
    if text == "auto":
        return os.cpu_count() or 1
    try:
        value = int(text)
    except ValueError:
        raise pytest.UsageError(f"--cpu-load: '{text}' is not a number or 'auto'") from None
    if value < 0:
        raise pytest.UsageError("--cpu-load: the number of busy processes cannot be negative")
    return value


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("cpu load", "keep the CPU busy while the tests run")
    group.addoption(
        "--cpu-load",
        default="0",
        metavar="N",
        help="run N busy processes during the session ('auto': one per core; default 0)",
    )
    group.addoption(
        "--cpu-load-nice",
        type=int,
        default=0,
        metavar="K",
        help="niceness of the busy processes (default 0: the same priority as the tests)",
    )
    group.addoption(
        "--cpu-load-limit",
        type=float,
        default=DEFAULT_LIMIT,
        metavar="SECONDS",
        help=f"each busy process stops itself after this long (default {DEFAULT_LIMIT:g})",
    )


class CpuLoad:
    """N busy processes, started together and stopped together."""

    def __init__(self, count: int, nice: int, limit: float) -> None:
        self.count, self.nice, self.limit = count, nice, limit
        self.processes: list[subprocess.Popen] = []
        self.started = 0.0
        self.cpu_seconds = 0.0
        self.wall_seconds = 0.0

    def start(self) -> None:
        self.started = time.monotonic()
        args = [str(os.getpid()), str(self.limit), str(self.nice)]
        for _ in range(self.count):
            self.processes.append(
                subprocess.Popen(
                    [sys.executable, "-c", WORKER, *args],
                    # Their own session: a Ctrl-C typed in the terminal reaches pytest, which
                    # stops them, instead of printing their KeyboardInterrupt.
                    start_new_session=True,
                    stdin=subprocess.DEVNULL,
                )
            )

    def stop(self) -> None:
        for proc in self.processes:
            if proc.returncode is None:
                os.kill(proc.pid, signal.SIGKILL)  # also fine when it has already ended
                _, status, usage = os.wait4(proc.pid, 0)  # reaps it, with its CPU time
                proc.returncode = os.waitstatus_to_exitcode(status)
                self.cpu_seconds += usage.ru_utime + usage.ru_stime
        if self.processes:
            self.wall_seconds = time.monotonic() - self.started
        self.processes = []

    def describe(self) -> str:
        return (
            f"cpu load: {self.count} busy process(es), nice {self.nice}, "
            f"each stops after {self.limit:g} s at most"
        )


def pytest_configure(config: pytest.Config) -> None:
    # Under pytest-xdist only the controlling process starts the load, not each worker.
    if hasattr(config, "workerinput"):
        return
    count = _count(config.getoption("cpu_load"))
    if count == 0:
        return
    load = CpuLoad(count, config.getoption("cpu_load_nice"), config.getoption("cpu_load_limit"))
    load.start()
    config.stash[_KEY] = load


def pytest_report_header(config: pytest.Config) -> str | None:
    load = config.stash.get(_KEY, None)
    return load.describe() if load else None


def pytest_terminal_summary(terminalreporter, exitstatus: int, config: pytest.Config) -> None:
    load = config.stash.get(_KEY, None)
    if load is None:
        return
    load.stop()
    own = resource.getrusage(resource.RUSAGE_SELF)
    terminalreporter.write_line(
        f"cpu load: {load.count} busy process(es) used {load.cpu_seconds:.0f} s of CPU "
        f"in {load.wall_seconds:.0f} s (pytest itself: {own.ru_utime + own.ru_stime:.0f} s)"
    )


def pytest_unconfigure(config: pytest.Config) -> None:
    load = config.stash.get(_KEY, None)
    if load is not None:
        load.stop()  # also when the session ended early: Ctrl-C, an internal error


_KEY = pytest.StashKey[CpuLoad]()
