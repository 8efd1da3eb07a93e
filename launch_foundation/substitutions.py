r"""Substitutions: the ``$(...)`` expressions in attribute values.

ROS 1: $(arg x) $(find pkg) $(env V) $(optenv V [default]) $(anon name) $(dirname) $(eval ...)
ROS 2: $(var x) $(env V [default]) $(find-pkg-share pkg) $(find-pkg-prefix pkg) $(dirname)
       $(anon name) $(not x) $(and x y) $(or x y) $(equals x y) $(eval ...) $(command ...)
       $(file-content PATH)
Substitutions nest (``$(var $(var which))``). In the ROS 2 format a backslash makes the next
character plain text (``\$(`` is no substitution, ``\'`` no quote), as launch's grammar reads it;
roslaunch has no escapes. $(command) runs a program, so it is refused
unless the user passes --allow-code; so is an $(eval) that needs code to compute
(launch_foundation/expressions.py reads the rest without running any).
"""

from __future__ import annotations

import atexit
import contextlib
import math
import os
import re
import selectors
import shlex
import shutil
import signal
import subprocess
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any, Protocol

from launch_foundation.errors import CodeRefused, LaunchError
from launch_foundation.expressions import BUILTINS, MATH, NeedsCode, evaluate
from launch_foundation.parse import Element
from ros_tutorials_common import packages
from ros_tutorials_common.bounded import MAX_INPUT_BYTES, InputError, read_text

TRUE_WORDS = ("true", "1")
_ESCAPE = re.compile(r"\\(.)", re.DOTALL)
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
    """What a substitution can see: the scope it is written in (resolve.Scope)."""

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


def substitute(text: str, context: Context, element: Element) -> str:
    """Replace every $(...) in text; refuse a result longer than MAX_SUBSTITUTED characters
    (arguments whose defaults repeat the one before grow tenfold a level: ten levels of a
    1.2 KB file took the launcher to 10.8 GB)."""
    escapes = context.fmt == "ros2"
    if "$(" not in text and not (escapes and "\\" in text):
        return text
    out, position, size = [], 0, 0
    while (start := _next_substitution(text, position, escapes)) >= 0:
        out.append(_plain(text[position:start], escapes))
        end = _closing_paren(text, start, element, escapes)
        value = _evaluate(text[start + 2 : end].strip(), context, element)
        size += start - position + len(value)
        if size > MAX_SUBSTITUTED:
            raise element.error(
                f"substitutions expand to more than {MAX_SUBSTITUTED:,} characters; refusing"
            )
        out.append(value)
        position = end + 1
    out.append(_plain(text[position:], escapes))
    result = "".join(out)
    context.charge(len(result), element)
    return result


def _next_substitution(text: str, position: int, escapes: bool) -> int:
    """Where the next ``$(`` not written as ``\\$(`` starts (ROS 2), or -1."""
    while (start := text.find("$(", position)) >= 0:
        if not escapes or not _escaped(text, start):
            return start
        position = start + 1
    return -1


def _escaped(text: str, index: int) -> bool:
    """Whether an odd number of backslashes stands right before ``text[index]``."""
    count = 0
    while index - count - 1 >= 0 and text[index - count - 1] == "\\":
        count += 1
    return count % 2 == 1


def _plain(text: str, escapes: bool) -> str:
    """Plain text of a ROS 2 attribute: a backslash gives the character after it (launch's
    replace_escaped_characters)."""
    return _ESCAPE.sub(r"\1", text) if escapes and "\\" in text else text


def _closing_paren(text: str, start: int, element: Element, escapes: bool = False) -> int:
    depth, index = 0, start + 1
    while index < len(text):
        char = text[index]
        if escapes and char == "\\":  # \( and \) are no parentheses (ROS 2)
            index += 2
            continue
        if char == "(":
            depth += 1
            if depth > MAX_NESTING:
                raise element.error(f"substitutions nested more than {MAX_NESTING} deep")
        elif char == ")":
            depth -= 1
            if depth == 0:
                return index
        index += 1
    raise element.error(f"unterminated substitution in {text!r}")


def _split_words(text: str, escapes: bool = False) -> list[str]:
    """Split on spaces that are outside quotes and outside nested $(...); drop the quotes.
    With ``escapes`` (ROS 2) a backslash and the character after it stay as written, for
    substitute() to read: they neither quote, split nor nest."""
    words: list[str] = []
    current: list[str] = []  # characters, joined once (adding to a string was quadratic)
    depth, quote, started, escaped = 0, "", False, False
    for char in text:
        if escaped:
            current.append(char)
            escaped = False
            continue
        if escapes and char == "\\":
            current.append(char)
            escaped = started = True
            continue
        if quote:
            if char == quote and depth == 0:
                quote = ""
                continue
        elif char in "'\"" and depth == 0:
            quote, started = char, True  # '' is an empty word, not no word
            continue
        elif char.isspace() and depth == 0:
            if started:
                words.append("".join(current))
            current, started = [], False
            continue
        depth += {"(": 1, ")": -1}.get(char, 0)
        current.append(char)
        started = True
    if started:
        words.append("".join(current))
    return words


def _evaluate(inner: str, context: Context, element: Element) -> str:
    name, _, rest = inner.partition(" ")
    table = ROS1 if context.fmt == "ros1" else ROS2
    if name not in table:
        known = ", ".join(f"$({known})" for known in table)
        raise element.error(f"unknown substitution $({name}); known here: {known}")
    if name == "command" and not context.allow_code:
        raise CodeRefused(f"{element.where}: $(command) runs a program named in the launch file")
    if context.fmt == "ros1" and name == "eval":
        return _ros1_eval(rest, context, element)  # ROS 1 eval sees raw Python, not $(...)
    split = _split_words(rest, escapes=context.fmt == "ros2")
    words = [substitute(word, context, element) for word in split]
    function, counts = table[name]
    if len(words) not in counts:
        raise element.error(f"$({name}) takes {_plural(counts)}, got {len(words)}: $({inner})")
    return function(words, context, element)


def _plural(counts: range) -> str:
    low, high = counts.start, counts.stop - 1
    return f"{low} argument(s)" if low == high else f"{low} to {high} arguments"


def _arg(words: list[str], context: Context, element: Element) -> str:
    return context.read_arg(words[0], element)


def _env(words: list[str], _context: Context, element: Element) -> str:
    value = os.environ.get(words[0], words[1] if len(words) > 1 else None)
    if value is None:
        raise element.error(f"environment variable {words[0]} is not set")
    return value


def _optenv(words: list[str], _context: Context, _element: Element) -> str:
    return os.environ.get(words[0], " ".join(words[1:]))


def _package_path(locate: Callable[[str], Path], words: list[str], element: Element) -> str:
    try:
        return str(locate(words[0]))
    except LookupError as error:
        raise element.error(str(error)) from None


def _find(words: list[str], _context: Context, element: Element) -> str:
    return _package_path(packages.package_folder, words, element)  # ROS 1: rospack find


def _find_share(words: list[str], _context: Context, element: Element) -> str:
    return _package_path(packages.share_directory, words, element)


def _find_prefix(words: list[str], _context: Context, element: Element) -> str:
    return _package_path(packages.prefix, words, element)


def _dirname(_words: list[str], context: Context, _element: Element) -> str:
    return str(context.file.parent)


def _anon(words: list[str], context: Context, _element: Element) -> str:
    return context.anon(words[0])


def _not(words: list[str], _context: Context, element: Element) -> str:
    return str(not to_bool(words[0], element, "$(not) argument")).lower()


def _and(words: list[str], _context: Context, element: Element) -> str:
    return str(all(to_bool(word, element, "$(and) argument") for word in words)).lower()


def _or(words: list[str], _context: Context, element: Element) -> str:
    return str(any(to_bool(word, element, "$(or) argument") for word in words)).lower()


def _param(words: list[str], context: Context, element: Element) -> str:
    """launch_ros's $(param NAME [DEFAULT]): the value a <set_parameter> before it in its scope
    gave NAME (the first such, as launch_ros reads its global parameters), as Python's str."""
    for name, value in context.params:
        if name == words[0]:
            return str(value)
    if len(words) > 1:
        return words[1]
    raise element.error(f"parameter {words[0]!r} not found (no <set_parameter> gave it before)")


def _equals(words: list[str], _context: Context, _element: Element) -> str:
    return str(words[0] == words[1]).lower()


def _python_eval(expression: str, names: dict, context: Context, element: Element) -> str:
    """An expression read by launch_foundation/expressions.py, or, if it needs code and the user
    allowed it, by Python's eval with the same names (and the whole math module)."""
    shown = f"$(eval {expression})"
    try:
        try:
            return str(evaluate(expression, names))
        except NeedsCode as part:
            if not context.allow_code:
                raise CodeRefused(
                    f"{element.where}: {shown} runs code written in the launch file ({part})"
                ) from None
        scope = {name: getattr(math, name) for name in dir(math) if not name.startswith("_")}
        return str(eval(expression, {**scope, **names}))  # opted in with --allow-code
    except CodeRefused:
        raise
    except Exception as error:
        raise element.error(f"{shown} failed: {error}") from None


def _auto(value: str) -> object:
    """An argument's text typed as roslaunch types it for $(eval): a number, a bool, or text."""
    try:
        if "." in value:
            return float(value)
        if "_" not in value:  # Python reads 1_000 as a number; roslaunch keeps it text
            return int(value)
    except ValueError:
        pass
    return value.lower() == "true" if value.lower() in ("true", "false") else value


def _ros1_eval(expression: str, context: Context, element: Element) -> str:
    if "__" in expression:  # roslaunch refuses these too (they reach Python's internals)
        raise element.error(f"$(eval {expression}): '__' is not allowed in $(eval)")
    names: dict = {name: _auto(value) for name, value in context.args.items()}
    # roslaunch's functions and constants win over arguments of the same name.
    names.update(MATH, **BUILTINS, true=True, false=False)
    names["arg"] = lambda name: _auto(context.read_arg(name, element))
    names["env"] = lambda name: _env([name], context, element)
    names["optenv"] = lambda name, default="": os.environ.get(name, default)
    names["find"] = lambda package: _find([package], context, element)
    names["anon"] = context.anon
    names["dirname"] = lambda: str(context.file.parent)
    return _python_eval(expression, names, context, element)


def _ros2_eval(words: list[str], context: Context, element: Element) -> str:
    return _python_eval(" ".join(words), {**MATH, **BUILTINS}, context, element)


def _command(words: list[str], _context: Context, element: Element) -> str:
    shown = f"$(command {' '.join(words)})"
    return run_command(" ".join(words), element.error, shown)


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


def _file_content(words: list[str], _context: Context, element: Element) -> str:
    """launch's FileContent: the text of a file (a relative path from the current directory,
    as ros2 launch opens it), at most 1 MiB."""
    try:
        return read_text(Path(words[0]))
    except InputError as error:
        raise element.error(f"$(file-content): {error}") from None


_SUBSTITUTED_DIR: list[Path] = []  # made once, removed when the launcher exits


def substituted_params_file(path: Path, context: Context, element: Element) -> Path:
    """launch_ros's ParameterFile(allow_substs=True): the file with its $(...) substituted,
    written to a file of its own for the node to read."""
    try:
        text = read_text(path)
    except InputError as error:
        raise element.error(str(error)) from None
    text = substitute(text, context, element)
    import tempfile

    if not _SUBSTITUTED_DIR:
        folder = Path(tempfile.mkdtemp(prefix="launch_params_"))
        atexit.register(shutil.rmtree, folder, ignore_errors=True)
        _SUBSTITUTED_DIR.append(folder)
    handle, name = tempfile.mkstemp(prefix=f"{path.stem}_", suffix=".yaml", dir=_SUBSTITUTED_DIR[0])
    with os.fdopen(handle, "w", encoding="utf-8") as out:
        out.write(text)
    return Path(name)


ANY = range(1, 100)
ROS1 = {
    "arg": (_arg, range(1, 2)),
    "find": (_find, range(1, 2)),
    "env": (_env, range(1, 2)),
    "optenv": (_optenv, ANY),
    "anon": (_anon, range(1, 2)),
    "dirname": (_dirname, range(0, 1)),
    "eval": (None, ANY),
}
ROS2 = {
    "var": (_arg, range(1, 2)),
    "env": (_env, range(1, 3)),
    "find-pkg-share": (_find_share, range(1, 2)),
    "find-pkg-prefix": (_find_prefix, range(1, 2)),
    "dirname": (_dirname, range(0, 1)),
    "anon": (_anon, range(1, 2)),
    "not": (_not, range(1, 2)),
    "and": (_and, range(2, 100)),
    "or": (_or, range(2, 100)),
    "equals": (_equals, range(2, 3)),
    "eval": (_ros2_eval, ANY),
    "command": (_command, ANY),
    "file-content": (_file_content, range(1, 2)),
    "param": (_param, range(1, 3)),
}
