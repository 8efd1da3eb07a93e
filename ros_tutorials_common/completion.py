"""TAB completion (argcomplete) of `ros2`, the launcher and the ROS 1 tools: the machinery, and
the names that come from the ament index.

As ros2cli does it: the shell runs the command itself with ``_ARGCOMPLETE=1`` and the line in
``COMP_LINE``/``COMP_POINT`` (argcomplete's protocol, registered by `source .venv/bin/activate`:
tools/ros_environment.py), and the command answers through argcomplete from its real parser,
where each argument names what completes it (``.completer = ...``). ``answer()`` is that answer;
each command's entry calls it before doing anything else, so a completion never runs the
command. Names of the running system come from the daemon (ros2cmd/completion.py); the names
here from the ament index: packages, their executables and launch files, interface types.

A completion answers within BUDGET seconds of its process's start or completes nothing (exit
status 1: the shell then offers nothing); COMPLETION_BUDGET_VARIABLE sets another budget.
"""

from __future__ import annotations

import argparse
import os
import signal
import time
from collections.abc import Callable, Iterable
from typing import Any

# The commands whose entry answers a completion, registered with the shell for TAB.
COMMANDS = (
    "ros2",
    "roslaunch",
    "rosrun",
    "rostopic",
    "rosservice",
    "rosparam",
    "rosnode",
    "rosmsg",
    "rossrv",
    "rosbag",
    "rospack",
    "roscore",
    "roscd",
    "rosed",
    "roscp",
    "rqt_graph",
    "rqt_console",
    "rqt_logger_level",
    "roslaunch-logs",
)
BUDGET = 0.15  # s from the process's start
COMPLETION_BUDGET_VARIABLE = "ROS_TUTORIALS_COMPLETION_BUDGET"
LAUNCH_SUFFIXES = (".launch", ".xml", ".py", ".yaml", ".yml")  # what packages.launch_files finds

Completer = Callable[..., Iterable[str]]


def requested() -> bool:
    """Whether the shell started this process to complete a command line."""
    return "_ARGCOMPLETE" in os.environ


def budget() -> float:
    """Seconds a completion may take from its process's start."""
    try:
        value = float(os.environ.get(COMPLETION_BUDGET_VARIABLE, BUDGET))
    except ValueError:
        return BUDGET
    return value if value > 0 else BUDGET


def _age() -> float:
    """Seconds since this process started (0 if the system cannot say)."""
    try:
        with open("/proc/self/stat") as stat:
            ticks = int(stat.read().rsplit(")", 1)[1].split()[19])
        age = time.clock_gettime(time.CLOCK_BOOTTIME) - ticks / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return 0.0
    return age if 0.0 <= age < 60.0 else 0.0


def remaining() -> float:
    """Seconds left of the budget (at least 0)."""
    return max(0.0, _deadline - time.monotonic())


_deadline = float("inf")


def _out_of_time(_signum: int, _frame: Any) -> None:
    os._exit(1)  # the shell completes nothing


def _ascii_number(text: str | None) -> int | None:
    return int(text) if text and text.isascii() and text.isdigit() else None


def well_formed() -> bool:
    """Whether the shell's request is argcomplete's protocol: ``_ARGCOMPLETE`` a word count
    from 1, ``COMP_LINE`` the line, ``COMP_POINT`` the cursor within it (ASCII digits)."""
    line = os.environ.get("COMP_LINE")
    point = _ascii_number(os.environ.get("COMP_POINT"))
    start = _ascii_number(os.environ.get("_ARGCOMPLETE"))
    if line is None or point is None or not start:
        return False
    # The shell counts characters or bytes (which one depends on its locale): either fits.
    return point <= len(line.encode(errors="surrogateescape"))


def arm() -> None:
    """Start the clock: at the end of the budget the process ends, having completed nothing.
    A request that is not argcomplete's protocol completes nothing at once."""
    global _deadline
    if not well_formed():
        os._exit(1)
    left = budget() - _age()
    _deadline = time.monotonic() + left
    if left <= 0:
        os._exit(1)
    signal.signal(signal.SIGALRM, _out_of_time)
    signal.setitimer(signal.ITIMER_REAL, left)


def answer(parser: argparse.ArgumentParser, skip: int = 0) -> None:
    """If the shell asks for completions, answer them from PARSER and end the process; else
    return. SKIP: words of the line before this parser's own (`launch` of `ros2 launch`)."""
    if not requested():
        return
    arm()
    import argcomplete  # only for a completion: it costs a few milliseconds

    if skip:  # argcomplete's count of the words before the arguments (as for `python x.py`)
        os.environ["_ARGCOMPLETE"] = str(int(os.environ["_ARGCOMPLETE"]) + skip)
    # -h and --help are not offered (as ros2cli's); an argument with no completer of its own
    # completes file names (argcomplete's default: a bag, a params file).
    argcomplete.autocomplete(parser, exclude=["-h", "--help"])
    os._exit(1)  # not reached: autocomplete ends the process


def line_words() -> list[str]:
    """The words of the line being completed, up to the cursor (the program's name first);
    the last one is the word under the cursor ('' after a space)."""
    from argcomplete.lexers import split_line

    line = os.environ.get("COMP_LINE", "")
    point = _ascii_number(os.environ.get("COMP_POINT"))
    _prequote, prefix, _suffix, words, _ = split_line(line, len(line) if point is None else point)
    return [*words, prefix]


def attach(parser: argparse.ArgumentParser, **completers: Completer) -> None:
    """Say what completes each of PARSER's arguments, by its dest:
    ``attach(p, package_name=package_names)``."""
    for action in parser._actions:
        if action.dest in completers:
            action.completer = completers[action.dest]  # type: ignore[attr-defined]


# The names of the ament index. Each completer takes argcomplete's keyword arguments
# (prefix, parsed_args, action, parser) and returns the candidates; argcomplete keeps those
# that start with what is typed.


def package_names(**_: Any) -> list[str]:
    """Every package of the ament index, and the seeds' names for this project's packages."""
    from ros_tutorials_common import ament, packages

    names = set(ament.packages())
    names.update(name for name in packages.PACKAGE_ALIASES if packages.resolve_package(name))
    return sorted(names)


def executable_names(parsed_args: argparse.Namespace, **_: Any) -> list[str]:
    """The executables of the package named before (`ros2 run PKG <TAB>`), as `ros2 pkg
    executables` lists them."""
    from ros_tutorials_common import packages

    package = getattr(parsed_args, "package_name", None)
    return sorted(packages.executable_files(package)) if package else []


def launch_file_names(package: str) -> list[str]:
    """The launch files of a package (share/PKG/launch/), as `ros2 launch PKG <TAB>` offers."""
    from ros_tutorials_common import packages

    try:
        found = packages.launch_packages(package)
        return sorted({path.name for name in found for path in packages.launch_files(name)})
    except (LookupError, OSError):
        return []


def launch_words(prefix: str, parsed_args: argparse.Namespace, **_: Any) -> list[str]:
    """The launcher's `[PKG] FILE [name:=value ...]`: first a package or a launch file here,
    then the package's launch files."""
    words = [word for word in getattr(parsed_args, "words", None) or [] if word]
    if not words:
        from argcomplete.completers import FilesCompleter

        files = FilesCompleter(LAUNCH_SUFFIXES)(prefix)
        return [*package_names(), *files]
    if len(words) == 1 and not os.path.isfile(words[0]):
        return launch_file_names(words[0])
    return []
