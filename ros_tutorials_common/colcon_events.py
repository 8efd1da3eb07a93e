"""colcon's event handler `failure_line`: a package whose build failed, in one line.

colcon prints a failed package's whole stderr: for a typo in a .msg that is CMake's report
around rosidl's, with three Python tracebacks, about 80 lines. In this environment colcon's
defaults (config/colcon_defaults.yaml, COLCON_DEFAULTS_FILE of the activated environment)
switch `console_stderr` off and this handler prints what failed, where, and the full log:

    error: tutorial_interfaces: src/tutorial_interfaces/msg/Num.msg:1: 'int64 num num': value
    'num' can not be converted to type 'int64' ... (full log: log/build_.../tutorial_interfaces/
    stdout_stderr.log)

(one line on the terminal). `colcon build --event-handlers console_stderr+` shows it all again.
`colcon test`: failed tests are colcon's test failures (`colcon test-result` lists them);
tests that could not even run (a test module that does not import) are one line too.
The handler is registered in pyproject.toml (entry point group colcon_core.event_handler).
"""

from __future__ import annotations

import re
import sys
from collections import defaultdict, deque
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from colcon_core.event.job import JobEnded
from colcon_core.event.output import StderrLine, StdoutLine
from colcon_core.event_handler import EventHandlerExtensionPoint
from colcon_core.location import get_log_path
from colcon_core.plugin_system import satisfies_version
from colcon_core.subprocess import SIGINT_RESULT
from colcon_core.verb.test import TestPackageArguments

from ros_tutorials_common.pypi_packages import not_available_line

MAX_REASON = 300  # characters: a reason longer than that is cut (the log has it all)
INTERFACE_SUFFIXES = ("_Request", "_Response", "_Goal", "_Result", "_Feedback")
# `colcon test`: pytest reports on standard output; its last lines say why it stopped.
KEPT_STDOUT_LINES = 200
# Terminal control sequences (CSI colours, OSC titles, two-character escapes): in a terminal
# colcon has CMake colour its messages, and the patterns below read the text without them.
ANSI_SEQUENCE = re.compile(r"\x1b(?:\[[0-?]*[ -/]*[@-~]|\][^\x07\x1b]*(?:\x07|\x1b\\)|[@-Z\\-_])")


class FailureLineEventHandler(EventHandlerExtensionPoint):
    """A failed package as one line: the file and line, the reason, and the full log."""

    # console_stderr's priority: the line comes before colcon's "Failed <<< PKG"
    PRIORITY = 110

    def __init__(self) -> None:
        super().__init__()
        satisfies_version(EventHandlerExtensionPoint.EXTENSION_POINT_VERSION, "^1.0")
        self._stderr: defaultdict[Any, list[bytes]] = defaultdict(list)
        self._stdout: defaultdict[Any, deque[bytes]] = defaultdict(
            lambda: deque(maxlen=KEPT_STDOUT_LINES)
        )

    def __call__(self, event: tuple[Any, Any]) -> None:
        data, job = event
        if isinstance(data, StderrLine):
            line = data.line
            self._stderr[job].append(line if isinstance(line, bytes) else line.encode())
        elif isinstance(data, StdoutLine) and testing(job):
            line = data.line
            self._stdout[job].append(line if isinstance(line, bytes) else line.encode())
        elif isinstance(data, JobEnded):
            lines = self._stderr.pop(job, [])
            stdout = self._stdout.pop(job, ())
            if data.rc and data.rc != SIGINT_RESULT:
                text = plain(b"".join(lines))
                source = Path(job.task_context.pkg.path)
                if testing(job):
                    output = plain(b"".join(stdout))
                    line = tests_not_run_line(data.identifier, source, text, output, data.rc)
                else:
                    line = failure_line(data.identifier, source, text, data.rc)
                print(line, file=sys.stderr)


def plain(output: bytes) -> str:
    """A tool's output as text without its terminal control sequences."""
    return ANSI_SEQUENCE.sub("", output.decode(errors="replace"))


def testing(job: Any) -> bool:
    """Whether JOB is a package's tests (`colcon test`), not its build."""
    return isinstance(job.task_context.args, TestPackageArguments)


def tests_not_run_line(
    package: str, source: Path, stderr: str, stdout: str, returncode: int
) -> str:
    """The line for PACKAGE whose tests could not run (failed tests are not a failed job:
    colcon counts them as test failures, and `colcon test-result` lists them)."""
    reason = pytest_stop_reason(stdout, source) or exception_line(stderr)
    reason = reason or first_error_line(stderr) or f"exit code {returncode}"
    line = f"error: {package}: the tests did not run: " + " ".join(reason.split())
    if len(line) > MAX_REASON + 40:
        line = line[: MAX_REASON + 37] + "..."
    log = get_log_path()
    if log is not None:
        line += f" (full log: {shown(log / package / 'stdout_stderr.log')})"
    return line


def pytest_stop_reason(stdout: str, source: Path) -> str:
    """pytest's reason for stopping before the tests ran: the test module it could not
    import (its `E   ...Error: ...` line), or its `ERROR: ...` usage line."""
    match = re.search(r"^ImportError while importing test module '(.+?)'", stdout, re.M)
    if match:
        after = stdout[match.end() :]
        error = re.search(r"^E\s+(\w+(?:Error|Exception)\b.*)$", after, re.M)
        where = shown(Path(match.group(1)))
        return f"{where}: {error.group(1)}" if error else where
    match = re.search(r"^_+ ERROR collecting (\S+) _+$", stdout, re.M)
    if match:
        after = stdout[match.end() :]
        error = re.search(r"^E\s+(\S.*)$", after, re.M)
        where = shown(source / match.group(1))
        return f"{where}: {error.group(1)}" if error else where
    match = re.search(r"^ERROR: (.+)$", stdout, re.M)
    return match.group(1) if match else ""


def failure_line(package: str, source: Path, stderr: str, returncode: int) -> str:
    """The line for PACKAGE (sources in SOURCE) whose build wrote STDERR and failed."""
    where, reason = explain(stderr, source)
    reason = " ".join(reason.split()) or f"the build failed (exit code {returncode})"
    if len(reason) > MAX_REASON:
        reason = reason[: MAX_REASON - 3] + "..."
    line = f"error: {package}: " + (f"{where}: " if where else "") + reason
    log = get_log_path()
    if log is not None:
        line += f" (full log: {shown(log / package / 'stdout_stderr.log')})"
    return line


def shown(path: Path) -> str:
    """PATH relative to the current directory when it is below it."""
    path = path.absolute()
    here = Path.cwd()
    return str(path.relative_to(here)) if path.is_relative_to(here) else str(path)


def paragraphs(text: str) -> list[str]:
    """TEXT's paragraphs, each on one line: CMake wraps the messages it prints at 80 columns."""
    return [" ".join(block.split()) for block in re.split(r"\n\s*\n", text) if block.strip()]


def explain(stderr: str, source: Path) -> tuple[str, str]:
    """Where (file:line, or '') and why a build failed, from what it wrote to stderr."""
    for finder in (rosidl_parser_error, unknown_package_error, cmake_error, compiler_error):
        found = finder(stderr, source)
        if found:
            return found
    reason = exception_line(stderr)
    if reason.startswith("CalledProcessError:") and "run_setup(" in reason:
        # colcon reads setup.py by running it: Python's error is printed above, not here.
        return shown(source / "setup.py"), "running setup.py failed (Python's error is above)"
    return "", reason or first_error_line(stderr)


def rosidl_parser_error(stderr: str, source: Path) -> tuple[str, str] | None:
    """rosidl's parser names the line and the interface (not the file): find them."""
    for paragraph in paragraphs(stderr):
        match = re.search(r"Error processing '(.*?)' of '\w+/(\w+)': '(.*)'$", paragraph)
        if match:
            line, name, why = match.groups()
            return located(source, name, line), f"'{line}': {why}"
        match = re.search(r"Error with: \w+ (\w+) (.*?)(?: Traceback|$)", paragraph)
        if match:
            name, line = match.groups()
            return located(source, name, line), f"'{line}': a field is a type and a name"
    return None


def unknown_package_error(stderr: str, source: Path) -> tuple[str, str] | None:
    """A field whose type is of a package that rosidl_generate_interfaces' DEPENDENCIES do not
    name: rosidl's type description generator fails on it with a KeyError."""
    missing = re.search(r"^KeyError: '(\w+)'$", stderr, re.M)
    target = re.search(r"rosidl_generator_type_description/\w+/\w+/(\w+)\.json", stderr)
    if not (missing and target and "rosidl_generator_type_description" in stderr):
        return None
    package, name = missing.group(1), target.group(1)
    file = interface_file(source, name)
    where = shown(file) if file else ""
    if file:
        for number, text in enumerate(file.read_text().splitlines(), 1):
            if text.strip().startswith(f"{package}/"):
                where = f"{shown(file)}:{number}"
                break
    return where, (
        f"uses a type of package '{package}', which is not in rosidl_generate_interfaces' "
        f"DEPENDENCIES (add it there, with find_package({package} REQUIRED) and "
        f"<depend>{package}</depend> in package.xml)"
    )


def cmake_error(stderr: str, source: Path) -> tuple[str, str] | None:
    """CMake's "CMake Error at FILE:LINE (COMMAND):" and its message; the package's own line
    of the call stack when the error is in a file of this environment's."""
    match = re.search(
        r"^CMake Error at (.+?):(\d+) \((\w+)\):\n(.*?)(?=^\S|\Z)", stderr, re.M | re.S
    )
    if not match:
        match = re.search(r"^CMake Error: ()()()(.*?)(?=^\S|\Z)", stderr, re.M | re.S)
        if not match:
            return None
    file, number, command, message = match.groups()
    where = f"{shown(source / file)}:{number}" if file else ""
    rest = stderr[match.end() :]
    stack = re.match(r"Call Stack \(most recent call first\):\n((?:  .*\n?)*)", rest)
    if stack and not (source / file).resolve().is_relative_to(source.resolve()):
        for entry in reversed(stack.group(1).splitlines()):
            own = re.match(r"\s+(.+?):(\d+) \((\w+)\)", entry)
            if own and not Path(own.group(1)).is_absolute():
                where = f"{shown(source / own.group(1))}:{own.group(2)}"
                break
    missing = re.search(r'configuration file provided by "(\w+)"', message)
    if command == "find_package" and missing:
        package = missing.group(1)
        impossible = not_available_line(package)
        if impossible:
            return where, f"find_package({package}): {impossible}"
        return where, (
            f"find_package({package}): no package '{package}' here (is the name right? a "
            "package of this workspace: is it in src/? otherwise: is it installed?)"
        )
    reason = exception_line(message) or (paragraphs(message) or [""])[0]
    return where, reason


def compiler_error(stderr: str, source: Path) -> tuple[str, str] | None:
    match = re.search(r"^(\S+?):(\d+):(?:\d+:)? (?:fatal )?error: (.+)$", stderr, re.M)
    if not match:
        return None
    file, number, reason = match.groups()
    return f"{shown(source / file)}:{number}", reason


def exception_line(text: str) -> str:
    """The last Python traceback's exception line, without its module ("ValueError: ...");
    CMake's wrapped lines of it joined again."""
    at = text.rfind("Traceback (most recent call last):")
    lines = text[at:].splitlines() if at >= 0 else []
    exception = re.compile(r"(\s*)(?:[a-z_]\w*\.)*([A-Z]\w*: \S.*)$")
    found = [i for i, line in enumerate(lines) if exception.match(line)]
    if not found:
        return ""
    indent, reason = exception.match(lines[found[-1]]).groups()
    for line in lines[found[-1] + 1 :]:
        if not (indent and line.strip() and line.startswith(indent) and line[len(indent)] != " "):
            break
        reason += " " + line.strip()
    return reason


def first_error_line(stderr: str) -> str:
    """The first line saying "error" (not make's "*** [...] Error"), else the last line."""
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    for line in lines:
        if re.search(r"\berror\b", line, re.I) and "***" not in line:
            return line
    return lines[-1] if lines else ""


def interface_files(source: Path, name: str) -> Iterator[Path]:
    for folder, extension in (("msg", "msg"), ("srv", "srv"), ("action", "action")):
        yield source / folder / f"{name}.{extension}"
    yield from sorted(source.rglob(f"{name}.*"))


def interface_file(source: Path, name: str) -> Path | None:
    """The .msg, .srv or .action file of an interface rosidl names (AddTwoInts_Request too)."""
    for candidate in (
        name,
        *(name.removesuffix(s) for s in INTERFACE_SUFFIXES if name.endswith(s)),
    ):
        for path in interface_files(source, candidate):
            if path.suffix in (".msg", ".srv", ".action") and path.is_file():
                return path
    return None


def located(source: Path, name: str, line: str) -> str:
    """file:line of the line rosidl quotes (which it quotes without its comment)."""
    file = interface_file(source, name)
    if file is None:
        return ""
    wanted = line.replace("\t", " ").strip()
    for number, text in enumerate(file.read_text().splitlines(), 1):
        if text.replace("\t", " ").split("#", 1)[0].strip() == wanted:
            return f"{shown(file)}:{number}"
    return shown(file)
