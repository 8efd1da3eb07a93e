"""Helpers for tests: spin until something happens, and run tutorial executables as processes.

Timeouts are generous (tests must pass on a loaded 2-core machine) and fail with a message
saying what was awaited; nothing here sleeps and hopes.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import TypeVar

import pytest
from rclpy.executors import Executor
from warm import Starter

from ros_tutorials_common import wait

T = TypeVar("T")
TIMEOUT = 30.0
# The console scripts (`ros2`, `rosbag`, `rosrun`, ...) installed beside this interpreter.
BIN = Path(sys.executable).parent
# This pytest process's warm-start server (tests/warm.py), set by conftest's ros_domain.
warm: Starter | None = None


def _warm(command: Sequence[str], env: Mapping[str, str], cold: bool) -> Starter | None:
    """The warm-start server if this command may start warm, else None (a cold start)."""
    if cold or warm is None or not warm.eligible(command, env):
        return None
    return warm


def _text(output: bytes) -> str:
    """Bytes a process wrote, as subprocess's text mode reads them (universal newlines)."""
    return output.decode(errors="replace").replace("\r\n", "\n").replace("\r", "\n")


def script(name: str) -> str:
    """A console script of this project, as the learner types it (run by this interpreter)."""
    return str(BIN / name)


def run(
    *args: str,
    timeout: float = TIMEOUT,
    input: str | None = None,
    stdin: int | None = None,
    cwd: str | None = None,
    env: dict[str, str] | None = None,
    cold: bool = False,
) -> subprocess.CompletedProcess:
    """Run a console script (`ros2`, `rosbag`, ...) to its end, as a learner types it.

    Output is captured as text. A command of this project in this session's environment
    starts warm (tests/warm.py) unless cold is true.
    """
    command = [str(BIN / args[0]), *args[1:]]
    environment = os.environ if env is None else env
    starter = _warm(command, environment, cold)
    if starter is None:
        try:
            return subprocess.run(
                command,
                capture_output=True,
                text=True,
                timeout=timeout,
                input=input,
                stdin=stdin,
                cwd=cwd,
                env=env,
            )
        except subprocess.TimeoutExpired:
            pytest.fail(f"{' '.join(args)} did not finish within {timeout:.0f} s")
    with contextlib.ExitStack() as files:
        into, out, err = (files.enter_context(tempfile.TemporaryFile()) for _ in range(3))
        if input is not None:
            into.write(input.encode())
            into.seek(0)
        given = stdin if input is None else into.fileno()
        streams = [0 if given is None else given, out.fileno(), err.fileno()]
        process = starter.start(command, environment, streams, cwd, new_session=False)
        try:
            code = process.wait(timeout)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
            pytest.fail(f"{' '.join(args)} did not finish within {timeout:.0f} s")
        out.seek(0)
        err.seek(0)
        return subprocess.CompletedProcess(command, code, _text(out.read()), _text(err.read()))


def finished(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    """Run a console script to its end, from a folder other than the project's."""
    return run(*args, cwd=tempfile.gettempdir(), env=env)


def ok(*args: str, timeout: float = TIMEOUT) -> str:
    """A console script that must succeed (exit 0, no traceback); its standard output."""
    result = run(*args, timeout=timeout)
    assert result.returncode == 0, f"{' '.join(args)} failed:\n{result.stderr}"
    assert "Traceback" not in result.stderr
    return result.stdout


def at_once(check: Callable[..., T], *commands: Sequence[str]) -> list[T]:
    """check(*command) (ok or fails) for each command, the commands started together as in
    as many terminals; the results in order. For commands that only look at the graph or
    fail on their own: none depends on another, and their waits for discovery overlap."""
    with ThreadPoolExecutor(max_workers=len(commands)) as pool:
        return list(pool.map(lambda command: check(*command), commands))


def fails(*args: str, timeout: float = TIMEOUT) -> str:
    """A console script that must fail: non-zero exit, one line on stderr, no traceback."""
    result = run(*args, timeout=timeout)
    assert result.returncode != 0, f"{' '.join(args)} succeeded:\n{result.stdout}"
    assert "Traceback" not in result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, f"expected one error line, got:\n{result.stderr}"
    return lines[0]


ROOT = Path(__file__).resolve().parents[1]
_FRAME = re.compile(r'  File "(?P<file>[^"]*)", line \d+, in (?P<function>.+)$')


def _ours(file: str) -> bool:
    """A file of this project's packages (not of the venv's, which may sit inside it)."""
    return file.startswith(str(ROOT)) and not file.startswith(sys.prefix)


# How rclpy refuses to go on in the context its signal handler has shut down (a node created
# while Ctrl-C or SIGTERM arrives, before it spins).
ROS_SHUT_DOWN = re.compile(
    r"RCLError: .*context (is not valid|is invalid)|NotInitializedException|"
    r"ExternalShutdownException"
)


SPINNING = {"spin", "spin_once", "spin_until_future_complete"}  # rclpy's: a node running
# What Python prints between an exception and the one raised while it was handled (or from it).
CHAINED = ("During handling of the above exception", "The above exception was the direct cause")
TRACEBACK = "Traceback (most recent call last):"
LABEL = re.compile(r"^\[[^\]]*\] ")  # the launcher's "[name] " before a child's lines


def _after_blanks(lines: list[str], at: int) -> int:
    while at < len(lines) and not lines[at].strip():
        at += 1
    return at


def error_reports(output: str) -> list[list[list[str]]]:
    """Python's reports of uncaught (or unraisable) errors in a program's output: each a list of
    blocks (a traceback's lines and the exception's line, or the exception's line alone), one
    per exception of a chain ("During handling of the above exception ...")."""
    programs: dict[str, list[str]] = {}  # the launcher's children's lines interleave
    for line in output.splitlines():
        label = LABEL.match(line)
        programs.setdefault(label[0] if label else "", []).append(
            line[label.end() if label else 0 :]
        )
    return [report for lines in programs.values() for report in _reports_in(lines)]


def _reports_in(lines: list[str]) -> list[list[list[str]]]:
    in_pth = False  # site's report of a failed .pth line is indented by two spaces
    for number, line in enumerate(lines):
        if line.startswith("Error processing line ") or line == "Remainder of file ignored":
            in_pth = line.startswith("Error")
        elif in_pth:
            lines[number] = line.removeprefix("  ")
    reports, at = [], 0
    while at < len(lines):
        follows = _after_blanks(lines, at + 1)
        chained = follows < len(lines) and lines[follows].startswith(CHAINED)
        alone = lines[at].rstrip(": ") == "KeyboardInterrupt"  # raised outside Python code
        if not (lines[at].startswith(TRACEBACK) or (lines[at][:1].strip() and chained) or alone):
            at += 1
            continue
        blocks = []
        while True:
            block = [lines[at]]
            if lines[at].startswith(TRACEBACK):
                while at + 1 < len(lines):  # frames, their source, blank lines; then the error
                    at += 1
                    block.append(lines[at])
                    if lines[at][:1].strip():
                        break
            blocks.append(block)
            follows = _after_blanks(lines, at + 1)
            if follows < len(lines) and lines[follows].startswith(CHAINED):
                at = _after_blanks(lines, follows + 1)
                continue
            at += 1
            break
        reports.append(blocks)
    return reports


def tracebacks_after_start(output: str, node: bool = False) -> list[str]:
    """Python's error reports in a program's output other than its own for a Ctrl-C while the
    program starts: a Ctrl-C before the program's first function runs (while site reads the
    .pth files or modules import) prints one, as for any Python program (docs/dev/limits.md).
    Such a report has a KeyboardInterrupt in its chain (alone, or as the cause of the error a
    C extension then raised: "ImportError: initialization failed") and no frame in a function
    of this project (a console script's or a package's, outside module level). A child's lines
    may carry the launcher's "[name] " label.

    NODE (a lesson node, as ros2/examples writes one: rclpy.init and the node's creation come
    before its try): its start lasts until it spins, so a KeyboardInterrupt through its main
    is accepted there, and so is rclpy's refusal to create the node in the context its signal
    handler has just shut down (ROS_SHUT_DOWN); not once a frame is in rclpy's spin.
    """
    found = []
    for blocks in error_reports(output):
        errors = [block[-1] for block in blocks]
        frames = [match for block in blocks for match in map(_FRAME.match, block) if match]
        if node:
            started = not any(frame["function"] in SPINNING for frame in frames)
        else:
            started = not any(
                frame["function"] != "<module>"
                and (_ours(frame["file"]) or frame["file"].startswith(str(BIN)))
                for frame in frames
            )
        interrupted = any(error.rstrip(": ") == "KeyboardInterrupt" for error in errors)
        refused = node and any(ROS_SHUT_DOWN.search(error) for error in errors)
        if not (started and (interrupted or refused)):
            found.append("\n".join(line for block in blocks for line in block))
    return found


def ready(server: NodeProcess) -> NodeProcess:
    """The service or parameter lesson's server, once it says it is ready."""
    server.wait_for_text("ready srv server!")
    return server


def retry_until(act: Callable[[], None], check: Callable[[], object]) -> object:
    """act(), then check() (which fails the test when it does not see the effect within its
    own short timeout), again and again until check() passes or TIMEOUT has gone by.

    For a command sent before discovery has joined sender and receiver: it is lost, as it
    would be for a person, who would press the key or send the command again.
    """
    deadline = time.monotonic() + TIMEOUT
    while True:
        act()
        try:
            return check()
        except pytest.fail.Exception:
            if time.monotonic() > deadline:
                raise


def spin_until(
    executor: Executor,
    condition: Callable[[], bool],
    timeout: float = TIMEOUT,
    what: str = "condition",
) -> None:
    """Spin until condition() is true (the tools' own wait loop); fail the test clearly
    after timeout seconds."""
    if not wait.spin_until(executor, condition, timeout, period=0.05):
        pytest.fail(f"timed out after {timeout:.0f} s waiting for {what}")


def _start_time(pid: int) -> int | None:
    """When a process started (clock ticks after boot, /proc/PID/stat); None if none runs."""
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return int(stat.read().rsplit(")", 1)[1].split()[19])
    except (OSError, IndexError, ValueError):
        return None


class NodeProcess:
    """A tutorial executable run as a real process, its output collected line by line."""

    def __init__(
        self,
        *args: str,
        env: dict[str, str] | None = None,
        prefix: Sequence[str] = (),
        cold: bool = False,
    ) -> None:
        # prefix: a command that runs Python for us, e.g. `ip netns exec NS` (two machines).
        self.args = [*prefix, sys.executable, *args]
        self.lines: list[str] = []
        self._changed = threading.Condition()
        self._interrupt_on: Callable[[str], bool] | None = None
        environment = {**os.environ, "PYTHONUNBUFFERED": "1", **(env or {})}
        starter = None if prefix else _warm(args, environment, cold)
        if starter is None:
            self.process = subprocess.Popen(
                self.args,
                stdout=subprocess.PIPE,
                stderr=subprocess.STDOUT,
                text=True,
                env=environment,
                start_new_session=True,
            )
            self._stdout = self.process.stdout
        else:
            read_end, write_end = os.pipe()
            try:
                streams = [0, write_end, write_end]
                self.process = starter.start(args, environment, streams, None, True)
            finally:
                os.close(write_end)
            self._stdout = open(read_end, encoding="utf-8", errors="replace")  # noqa: SIM115
        self._started_at = _start_time(self.process.pid)  # tells this process from a new one
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self._stdout is not None
        for line in self._stdout:
            with self._changed:
                self.lines.append(line.rstrip("\n"))
                if self._interrupt_on is not None and self._interrupt_on(self.lines[-1]):
                    self._interrupt_on = None
                    self.process.send_signal(signal.SIGINT)
                self._changed.notify_all()
        self._stdout.close()
        with self._changed:
            self._changed.notify_all()

    @property
    def output(self) -> str:
        with self._changed:
            return "\n".join(self.lines)

    def wait_for_output(
        self, condition: Callable[[list[str]], bool], timeout: float = TIMEOUT, what: str = "output"
    ) -> list[str]:
        """Wait until condition(lines) holds; fail with the output so far after timeout."""
        deadline = time.monotonic() + timeout
        with self._changed:
            while not condition(self.lines):
                remaining = deadline - time.monotonic()
                if remaining <= 0 or (
                    self.process.poll() is not None and not self._reader.is_alive()
                ):
                    pytest.fail(
                        f"{what} not seen from {' '.join(self.args[1:])}; "
                        f"output was:\n" + "\n".join(self.lines[-40:])
                    )
                self._changed.wait(min(remaining, 0.5))
            return list(self.lines)

    def wait_for_text(self, text: str, count: int = 1, timeout: float = TIMEOUT) -> list[str]:
        """Wait until count lines contain text (fails with the output so far otherwise)."""
        return self.wait_for_output(
            lambda lines: sum(text in line for line in lines) >= count,
            timeout,
            what=text if count == 1 else f"{count} lines with {text!r}",
        )

    def interrupt_when(self, seen: Callable[[str], bool]) -> None:
        """Ctrl-C the process the moment it prints a line for which seen(line) is true.

        Sent from the thread that reads the output, with no delay after the line: the
        hardest moment for a program whose handling of Ctrl-C changes around that line.
        """
        with self._changed:
            if any(seen(line) for line in self.lines):
                self.process.send_signal(signal.SIGINT)
            else:
                self._interrupt_on = seen

    def interrupt(self, timeout: float = TIMEOUT) -> int:
        """Ctrl-C the process (SIGINT) and return its exit code."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
        return self.wait(timeout)

    def wait(self, timeout: float = TIMEOUT) -> int:
        try:
            code = self.process.wait(timeout)
        except subprocess.TimeoutExpired:
            stuck = self.where_stuck()
            self.kill()
            pytest.fail(
                f"{' '.join(self.args[1:])} did not exit within {timeout:.0f} s; output:\n"
                + "\n".join(self.lines[-120:])
                + stuck
            )
        self._reader.join(timeout)
        return code

    def where_stuck(self) -> str:
        """For a failure message: every thread's stack of the running process, native ones
        from gdb where it is installed, then Python's (the fault handler's, on SIGABRT)."""
        native = ""
        if shutil.which("gdb"):
            gdb = ["gdb", "-p", str(self.process.pid), "-batch", "-ex", "thread apply all bt 25"]
            with contextlib.suppress(subprocess.SubprocessError, OSError):
                found = subprocess.run(gdb, capture_output=True, text=True, timeout=60)
                native = "\n--- gdb ---\n" + found.stdout[-20000:] + found.stderr[-2000:]
        with contextlib.suppress(OSError):
            self.process.send_signal(signal.SIGABRT)  # PYTHONFAULTHANDLER (conftest)
        with contextlib.suppress(subprocess.TimeoutExpired):
            self.process.wait(5)
        self._reader.join(5)
        return native

    def kill(self) -> None:
        """SIGKILL to the process's whole group (it leads a session of its own), also when
        the leader has ended already: children it started must not outlive the test. Not
        when its process id now names another process (ended and reaped long ago, the id
        given again to a process that may lead a group of another test's)."""
        if _start_time(self.process.pid) in (None, self._started_at):
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.killpg(self.process.pid, signal.SIGKILL)
        self.process.wait()
