"""Where the project starts a lesson node: this project's DDS defaults (after the environment
check `ros2 run` makes), then the lesson's own ``main()``, and rclpy's shutdown race taken for
the stop it is. Two ways in, one ``start``:

- the lessons' console scripts (``topic_publisher``, ``service_client 2 3``, ...).
  pyproject.toml's [project.scripts] is the one place a lesson's script is named: its value
  names the lesson module after this module,
  ``ros_tutorials_common.lesson_scripts:ros_tutorials_topic.publisher``, and the script pip
  writes runs ``from ros_tutorials_common.lesson_scripts import ros_tutorials_topic`` then
  ``ros_tutorials_topic.publisher()``: ``run("ros_tutorials_topic.publisher")``;
- `ros2 run`, rosrun and the launcher (ros_tutorials_common/packages.py's command lines):
  ``python -m ros_tutorials_common.lesson_scripts ros_tutorials_topic.talker ARGS``, which runs
  the module as ``python -m ros_tutorials_topic.talker ARGS`` would.

A lesson whose thread outlives its spin (the action server's goal, in the thread of rclpy's
MultiThreadedExecutor) makes rclpy report that thread's calls on the context Ctrl-C or SIGTERM
shut down: ``RaceReports`` keeps those reports off standard error, for both ways in.

A lesson file is plain rclpy and handles none of this, and its package imports nothing of the
project: a learner's copy behaves like the original (docs/lesson-files.md). The lesson is
imported by the name given, after the defaults, so nothing here imports a lesson package (the
lessons sit above this floor).
"""

from __future__ import annotations

import atexit
import contextlib
import importlib
import os
import runpy
import signal
import sys
import threading
from collections.abc import Callable
from typing import Any

from ros_tutorials_common import shutdown
from ros_tutorials_common.dds import apply_dds_defaults, environment_problem

THIS = "ros_tutorials_common.lesson_scripts"  # also when run as __main__
# The packages whose modules a console script may name (the lessons and the demo nodes).
LESSON_PACKAGE_PREFIX = "ros_tutorials_"
# The packages of plain rclpy nodes that `ros2 run` and the launcher start through here: the
# lessons, ROS 2's demo nodes, and the tf2 pages' demo package.
PLAIN_NODE_PACKAGES = (
    "ros_tutorials_topic",
    "ros_tutorials_service",
    "ros_tutorials_parameter",
    "ros_tutorials_action",
    "ros_tutorials_demo_nodes",
    "turtle_tf2_py",
)


def lesson_module(script_value: str) -> str | None:
    """The lesson module a console script's ``module:attr`` value runs, or None if it is not
    a lesson's script."""
    module, _, attribute = script_value.partition(":")
    if module.strip() != THIS:
        return None
    return attribute.strip()


def command(module: str) -> list[str]:
    """The command line that starts MODULE, a plain rclpy node's module, through here."""
    return [sys.executable, "-m", THIS, module]


def started_module(line: list[str]) -> str | None:
    """The module a command line of ``command()`` starts, or None for another command line."""
    return line[3] if line[1:3] == ["-m", THIS] and len(line) > 3 else None


def start(main: Callable[[], Any]) -> Any:
    """Check the environment, apply the DDS defaults, then run ``main``: rclpy's race on
    Ctrl-C/SIGTERM ends it with status 0 and nothing printed (``shutdown.is_shutdown_race``: its
    handler shut ROS down under the spin or a timer's publish; ``shutdown.interrupted``: the
    Ctrl-C landed while rclpy's C++ converted a message, which pybind11 reports as its own
    RuntimeError), and a Ctrl-C that Python lost in a ``__del__`` (rclpy's Future's) is not
    printed: rclpy's handler has shut ROS down all the same, which ends the spin."""
    problem = environment_problem()  # as `ros2 run` checks: rclpy.init would fail
    if problem:
        raise SystemExit(f"error: {problem}")
    apply_dds_defaults()  # before the lesson's rclpy.init, which is when DDS reads them
    previous_handler = signal.getsignal(signal.SIGINT)
    shutdown.count_presses(deliver_lost=False)  # rclpy's handler calls it after its own
    previous = sys.unraisablehook

    def unraisable(what: Any) -> None:
        if not isinstance(what.exc_value, KeyboardInterrupt):
            previous(what)

    sys.unraisablehook = unraisable
    try:
        return main()
    except RuntimeError as error:
        if not (shutdown.is_shutdown_race(error) or shutdown.interrupted(error)):
            raise
        return 0
    finally:
        sys.unraisablehook = previous
        main_thread = threading.current_thread() is threading.main_thread()
        if main_thread and shutdown.counts_presses():  # for a caller that goes on (a test)
            signal.signal(signal.SIGINT, previous_handler)


# What rclpy prints of a thread that carries on after its signal handler shut ROS down under
# the spin (an action server's goal, in the executor's thread): rclpy's action server reports
# the goal's feedback, final state and result failing on the shut-down context, and rcl each
# log line it could not publish to /rosout.
RACE_REPORTS = (
    "Failed to publish log message to rosout: ",
    "]: Error raised in execute callback: ",  # and the traceback rclpy prints after it
    "]: Failed to send result response ",
    "]: Goal state not set, assuming aborted.",
)
FOLLOWED_BY_TRACEBACK = RACE_REPORTS[1]
LONGEST_LINE = 1 << 16  # a longer line is passed on in parts, never held whole


class RaceReports:
    """The process's standard error (fd 2) through a thread of its own that passes it on,
    except, once ROS is down, ``RACE_REPORTS`` and the traceback after an execute callback's
    (judged when read: one written just before the stop goes too). ``close`` (at exit, once
    the threads Python waits for have ended) puts standard error back and passes on the rest.
    What the process writes in the instant before it is killed (SIGKILL, a crash) may be lost
    with the thread."""

    def __init__(self) -> None:
        self.target = os.dup(2)
        read_end, write_end = os.pipe()
        os.dup2(write_end, 2)
        os.close(write_end)
        self.reader = os.fdopen(read_end, "rb", buffering=0)
        self.traceback: str | None = None  # the state of a traceback after a race report
        self.thread = threading.Thread(target=self._pass_on, name="stderr", daemon=True)
        self.thread.start()

    def _pass_on(self) -> None:
        pending = b""
        while chunk := self.reader.read(LONGEST_LINE):
            *lines, pending = (pending + chunk).split(b"\n")
            if len(pending) >= LONGEST_LINE:
                lines.append(pending)
                pending = b""
            kept = [line for line in lines if not self._race_report(line.decode(errors="replace"))]
            self._write(b"".join(line + b"\n" for line in kept))
        self._write(pending)

    def _race_report(self, line: str) -> bool:
        if self.traceback == "inside":  # its frames are indented; its last line, the error, not
            self.traceback = "inside" if line.startswith(" ") else None
            return True
        if self.traceback == "expected" and line.startswith("Traceback "):
            self.traceback = "inside"
            return True
        if not any(report in line for report in RACE_REPORTS) or _ros_is_up():
            return False
        if FOLLOWED_BY_TRACEBACK in line:
            self.traceback = "expected"
        return True

    def _write(self, data: bytes) -> None:
        with contextlib.suppress(OSError):  # the reader has gone: so has what it would read
            while data:
                data = data[os.write(self.target, data) :]

    def close(self) -> None:
        with contextlib.suppress(OSError):
            sys.stderr.flush()
        os.dup2(self.target, 2)  # closes the pipe's last write end: the thread reads its end
        self.thread.join(timeout=5.0)

    @classmethod
    def for_this_process(cls) -> None:
        """From now until the process ends (none when standard error cannot be piped)."""
        if os.isatty(2):  # rcutils colours its lines for a terminal: the pipe still leads there
            os.environ.setdefault("RCUTILS_COLORIZED_OUTPUT", "1")
        try:
            reports = cls()
        except OSError:
            return
        atexit.register(reports.close)


def _ros_is_up() -> bool:
    rclpy = sys.modules.get("rclpy")  # the lesson's: no report of rclpy's comes before it
    try:
        return rclpy is not None and rclpy.ok()
    except Exception:  # the interpreter is ending: so is ROS
        return False


def run(module: str) -> int | None:
    """A lesson's console script: ``module``'s main(), started as ``start`` says."""
    return start(lambda: importlib.import_module(module).main())


def run_as_main(module: str, args: list[str]) -> None:
    """``python -m module ARGS``, started as ``start`` says."""
    sys.argv = [module, *args]  # runpy puts the module's file first, as `python -m` does
    start(lambda: runpy.run_module(module, run_name="__main__", alter_sys=True))


class _Package:
    """``ros_tutorials_topic`` as a script's first name: its attributes are the lessons' runs."""

    def __init__(self, name: str) -> None:
        self.name = name

    def __getattr__(self, module: str) -> Callable[[], int | None]:
        if module.startswith("__"):
            raise AttributeError(module)

        def script() -> int | None:
            RaceReports.for_this_process()
            return run(f"{self.name}.{module}")

        return script


def __getattr__(name: str) -> _Package:
    """The first name of a lesson script's value (``... import ros_tutorials_topic``)."""
    if not name.startswith(LESSON_PACKAGE_PREFIX):
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return _Package(name)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(f"usage: python -m {THIS} PACKAGE.MODULE [ARGS ...]")
    RaceReports.for_this_process()
    run_as_main(sys.argv[1], sys.argv[2:])
