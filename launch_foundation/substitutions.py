"""The rules of ``$(...)`` text every layer of the launch stack shares: how a condition's or
flag's text reads as a bool (``to_bool``), the expansion caps (one attribute, nesting, the
whole launch), running a command for ``$(command)``, launch's ``Command`` and roslaunch's
``<param command>`` (bounded in time and output; its processes ended with it), and a
parameters file with its ``$(...)`` performed. The engines that read ``$(...)`` stand above
it: launch.frontend's scanner for the ROS 2 formats, launcher/ros1_substitutions.py for
roslaunch's.
"""

from __future__ import annotations

import atexit
import contextlib
import os
import selectors
import shlex
import shutil
import signal
import subprocess
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any, Protocol

from launch_foundation.errors import LaunchError
from launch_foundation.parse import Element
from ros_tutorials_common.bounded import MAX_INPUT_BYTES, InputError, read_text

TRUE_WORDS = ("true", "1")
MAX_NESTING = 50  # $(...) inside $(...): deeper is refused before it exhausts Python's stack
MAX_SUBSTITUTED = 1024 * 1024  # characters one attribute's substitutions may expand to
COMMAND_SECONDS = 60.0  # how long a command of $(command), Command or <param command> may run
# How long a command's output may stay open after the command ended (held by a process it
# left in the background, which would otherwise hold the launch until COMMAND_SECONDS).
BACKGROUND_SECONDS = 2.0
# Characters all the substitutions of one launch may expand to: each attribute within its cap,
# a large argument used in thousands of attributes would still fill the memory.
MAX_LAUNCH_SUBSTITUTED = 64 * 1024 * 1024
FALSE_WORDS = ("false", "0")


class Context(Protocol):
    """What a front-end's substitution can see: the scope it is written in (the launcher's
    launcher/scope.py Scope)."""

    fmt: str
    file: Path
    args: dict[str, str]
    params: list[tuple[str, Any]]  # launch_ros's global parameters (SetParameter)

    @property
    def allow_code(self) -> bool: ...

    def anon(self, name: str) -> str: ...

    def read_arg(self, name: str, element: Element) -> str: ...

    def charge(self, size: int, element: Element) -> None:
        """Count ``size`` characters toward the launch's MAX_LAUNCH_SUBSTITUTED."""


def to_bool(value: str, where: Element | str, what: str) -> bool:
    """A condition or flag's text as both formats and launch's Python API read it: true,
    false, 1 or 0, any case; else an error at ``where`` (an element or a file:line)."""
    word = value.strip().lower()
    if word in TRUE_WORDS:
        return True
    if word in FALSE_WORDS:
        return False
    message = f"{what} must be true, false, 1 or 0, not {value!r}"
    raise where.error(message) if isinstance(where, Element) else LaunchError(f"{where}: {message}")


def run_command(
    text: str,
    error: Callable[[str], Exception],
    shown: str,
    env: dict[str, str] | None = None,
    on_stderr: str = "ignore",
) -> str:
    """What the command line ``text`` prints: launch's Command, $(command) and roslaunch's
    <param command>. ``error`` makes the exception for a message (with the file:line),
    ``shown`` names the command in it. ``on_stderr`` "fail" (launch's Command) fails on
    anything printed to stderr; "capture" adds it to the output."""
    try:
        command = shlex.split(text)
    except ValueError as problem:
        raise error(f"{shown}: {problem}") from None
    if not command:
        raise error(f"{shown}: no command")
    # Its output is read with the same limit as a file (1 MiB), within COMMAND_SECONDS in all;
    # stderr goes to a file, so neither pipe can fill up and block it, nor fill the launcher's
    # memory. No terminal input (a command that reads stdin ends at once), and a session of its
    # own, so that one kill reaches what it left running in the background too; what left that
    # session and still holds its output is found by the output it holds (_end_command).
    import tempfile  # here, as below: most launches run no command and substitute no file

    deadline = time.monotonic() + COMMAND_SECONDS
    with tempfile.TemporaryFile() as errors, _sigterm_raises():
        try:
            process = subprocess.Popen(
                command, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=errors,
                env=env, start_new_session=True,
            )  # fmt: skip
        except OSError as problem:
            raise error(f"{shown} failed: {problem}") from None
        assert process.stdout is not None
        ended = False
        try:
            out = _read_until(process, deadline, error, shown)
            ended = True
            try:
                code = process.wait(timeout=max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                raise error(f"{shown} failed: still running after {COMMAND_SECONDS:g} s") from None
        finally:
            _end_command(process, holders=not ended)
        errors.seek(0)
        stderr = errors.read(64 * 1024).decode(errors="replace")
    if code != 0 or (stderr.strip() and on_stderr == "fail"):
        reason = stderr.strip().splitlines()[-1:] or [f"exit code {code}"]
        raise error(f"{shown} failed: {reason[0]}")
    try:
        text = out.decode()
    except UnicodeDecodeError:
        raise error(f"{shown} printed something that is not UTF-8 text") from None
    return text + stderr if on_stderr == "capture" else text


class Terminated(BaseException):
    """SIGTERM arrived while a command ran: raised to end the command first (run_command's
    finally), then the signal is delivered again as it would have been."""


@contextlib.contextmanager
def _sigterm_raises() -> Iterator[None]:
    """While a command runs, SIGTERM (as Ctrl-C already does) unwinds through run_command, so
    that its processes are ended before the launcher ends; then the signal takes its course."""
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def raise_terminated(_signum: int, _frame: object) -> None:
        raise Terminated

    previous = signal.signal(signal.SIGTERM, raise_terminated)
    try:
        yield
    except Terminated:
        signal.signal(signal.SIGTERM, previous)
        signal.raise_signal(signal.SIGTERM)  # the default ends this process with SIGTERM
        raise SystemExit(128 + signal.SIGTERM) from None  # a handler of its own returned
    finally:
        signal.signal(signal.SIGTERM, previous)


def _end_command(process: subprocess.Popen, holders: bool) -> None:
    """End the command's session and, if its output is still open (``holders``: it was not
    read to its end), every process that holds it: a background process that called setsid
    left the session but not the pipe. Then reap the command."""
    assert process.stdout is not None
    with contextlib.suppress(ProcessLookupError):
        os.killpg(process.pid, signal.SIGKILL)  # ended, or being ended: what it left behind
    if holders:
        pipe = os.fstat(process.stdout.fileno()).st_ino
        for pid in _pipe_holders(pipe):
            with contextlib.suppress(ProcessLookupError, PermissionError):
                group = os.getpgid(pid)
                if group != os.getpgrp():  # its own group, made by setsid: all of it
                    os.killpg(group, signal.SIGKILL)
                else:
                    os.kill(pid, signal.SIGKILL)
    process.wait()
    process.stdout.close()


def _pipe_holders(inode: int) -> list[int]:
    """The processes (other than this one) with a file descriptor on pipe ``inode``: Linux's
    /proc, read only where this user may (the command's processes are this user's)."""
    link = f"pipe:[{inode}]"
    found = []
    me = os.getpid()
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit() or int(entry.name) == me:
            continue
        try:
            for descriptor in os.scandir(f"/proc/{entry.name}/fd"):
                if os.readlink(descriptor.path) == link:
                    found.append(int(entry.name))
                    break
        except OSError:  # not ours to read, or gone meanwhile
            continue
    return found


def _read_until(
    process: subprocess.Popen, deadline: float, error: Callable[[str], Exception], shown: str
) -> bytes:
    """A command's stdout until it closes, at most MAX_INPUT_BYTES, before the deadline; a
    command that ended while its output stays open (held by a process it left in the
    background) is given BACKGROUND_SECONDS more, not the whole time, then refused."""
    assert process.stdout is not None
    out = bytearray()
    ended_at: float | None = None
    with selectors.DefaultSelector() as selector:
        selector.register(process.stdout, selectors.EVENT_READ)
        while True:
            now = time.monotonic()
            if ended_at is None and process.poll() is not None:
                ended_at = now
            if ended_at is not None and now - ended_at > BACKGROUND_SECONDS:
                raise error(
                    f"{shown} failed: it ended, but a process it left in the background "
                    "keeps its output open (redirect that process's output: > /dev/null)"
                )
            left = deadline - now
            if left <= 0:
                raise error(f"{shown} failed: still running after {COMMAND_SECONDS:g} s")
            if not selector.select(min(left, 0.25 if ended_at is None else 0.1)):
                continue
            chunk = os.read(process.stdout.fileno(), 65536)
            if not chunk:
                return bytes(out)
            out += chunk
            if len(out) > MAX_INPUT_BYTES:
                raise error(f"{shown} printed more than 1 MiB")


_SUBSTITUTED_DIR: list[Path] = []  # made once, removed when the launcher exits


def substituted_params_file(path: Path, substitute: Callable[[str], str], element: Element) -> Path:
    """launch_ros's ParameterFile(allow_substs=True): the file with its $(...) performed by
    ``substitute`` (the front-end's engine), written to a file of its own for the node."""
    try:
        text = read_text(path)
    except InputError as error:
        raise element.error(str(error)) from None
    text = substitute(text)
    import tempfile

    if not _SUBSTITUTED_DIR:
        folder = Path(tempfile.mkdtemp(prefix="launch_params_"))
        atexit.register(shutil.rmtree, folder, ignore_errors=True)
        _SUBSTITUTED_DIR.append(folder)
    handle, name = tempfile.mkstemp(prefix=f"{path.stem}_", suffix=".yaml", dir=_SUBSTITUTED_DIR[0])
    with os.fdopen(handle, "w", encoding="utf-8") as out:
        out.write(text)
    return Path(name)
