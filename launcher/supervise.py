"""Supervise: start the planned processes, show their output, respawn them, shut them down.

(About 690 lines: one event loop, whose starting, output, respawn, steps and stopping share its
state and are read together; the guardian is guardian.py, the plan plan.py.)

How nothing is left behind:
- the launcher runs under its guardian (launcher/guardian.py), the process the user started:
  it passes signals on, is a child subreaper above the launcher, and when the launcher has
  ended, however, it kills whatever is still below it. If the guardian is killed, the
  launcher gets SIGTERM (``PR_SET_PDEATHSIG``) and kills everything at once (``abandoned``);
- each child runs in its own process group (``start_new_session``), so a signal to the group
  reaches the grandchildren too; Ctrl-C or SIGTERM makes the launcher stop the children in
  order: SIGINT, after ``sigterm_timeout`` SIGTERM, after ``sigkill_timeout`` SIGKILL;
- each child asks the kernel to SIGKILL it when the launcher dies (``PR_SET_PDEATHSIG``), even
  if the launcher is SIGKILLed and can do nothing. The kernel ties this to the *thread* that
  forked, so every child is started from the main thread;
- a tiny group keeper process, forked before the first child, kills the process groups the
  launcher leaves behind if it dies, which covers the grandchildren PDEATHSIG does not reach
  even when the guardian dies at the same moment;
- when a child exits, whatever it left in its process group is killed before it is reaped;
- the launcher is a child subreaper (``PR_SET_CHILD_SUBREAPER``): a grandchild that left its
  process group (``setsid``) is adopted by the launcher, not by init, when its parent dies,
  and is stopped with the rest at the end (SIGTERM, then SIGKILL).

Timers and event handlers (the plan's ``When``): a process or a step waits for its time in
``pending``; the events (a process started, exited, printed a line; the launch shuts down)
are raised in the main thread, where every process is started. A line a handler listens to
reaches the main thread through a queue.

What the launcher says has two spellings (``Supervisor.ros2``): ``ros2 launch`` speaks as ros2
launch does (``[INFO] [launch]: All log files can be found below DIR``, ``[INFO]
[turtlesim_node-1]: process started with pid [1234]``, each process named after its
executable and numbered in the order they start), ``roslaunch`` and ``python -m launcher``
keep this launcher's own ``[launcher] started ns1/talker (pid 1234)``. The same facts either way,
and this launcher's shutdown and error lines in both, except the escalation: ``ros2 launch``
says ``process[talker-1] failed to terminate '5' seconds after receiving 'SIGINT', escalating
to 'SIGTERM'`` as ros2 launch does.

Output is relayed line by line, and a line is never held whole: it is read in pieces of at
most MAX_LINE_BYTES. The log file gets every byte; the screen shows a longer line cut at
MAX_LINE_BYTES, with a note saying so. A KeyboardInterrupt traceback from a child the
launcher itself is stopping (Ctrl-C while it was still importing) is shown as one line;
the log file keeps the traceback.
"""

from __future__ import annotations

import contextlib
import ctypes
import os
import queue
import shlex
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import IO, ClassVar

from launch_foundation.declarations import Step, shown_line
from launch_foundation.errors import LaunchError
from launcher import guardian
from launcher.plan import ProcessSpec, program_path
from ros_tutorials_common.ament import apply_ament_defaults
from ros_tutorials_common.dds import apply_dds_defaults

POLL_SECONDS = 0.05
STABLE_RUN_SECONDS = 10.0  # a process that ran this long before exiting did not "fail quickly"
BACKOFF_FIRST_SECONDS = 0.5  # extra respawn delay after the first quick failure, doubled each time
BACKOFF_MAX_SECONDS = 30.0
PR_SET_PDEATHSIG = 1
PR_SET_CHILD_SUBREAPER = 36
MAX_LINE_BYTES = 64 * 1024  # the most of one output line held in memory or shown on screen
MAX_TRACEBACK_LINES = 400  # the most lines of a stopping child's traceback held back
ADOPTED_STOP_SECONDS = 5.0  # adopted processes: from SIGTERM to SIGKILL

_libc = ctypes.CDLL(None, use_errno=True)


def make_log_dir() -> Path:
    """A new folder for this launch's logs, under $ROS_LOG_DIR or ~/.ros/log, named as ros2
    launch names it: 2026-11-24-09-09-47-123456-HOST-PID."""
    base = Path(os.environ.get("ROS_LOG_DIR") or Path.home() / ".ros" / "log")
    now = time.time()
    stamp = time.strftime("%Y-%m-%d-%H-%M-%S", time.localtime(now))
    path = base / f"{stamp}-{int(now % 1 * 1e6):06d}-{socket.gethostname()}-{os.getpid()}"
    try:
        path.mkdir(parents=True, exist_ok=True)
        (path / ".writable").touch()
        (path / ".writable").unlink()
    except OSError as error:
        where = "ROS_LOG_DIR" if os.environ.get("ROS_LOG_DIR") else "the log folder"
        raise LaunchError(
            f"cannot write the launch's logs to {path} ({where}): {error.strerror or error}"
        ) from None
    return path


def _exited(pid: int) -> bool:
    """Has the child exited? Leaves it unreaped, so its process group id stays reserved."""
    try:
        return os.waitid(os.P_PID, pid, os.WEXITED | os.WNOHANG | os.WNOWAIT) is not None
    except ChildProcessError:
        return True


def _kill_group(pgid: int, sig: int) -> None:
    with contextlib.suppress(ProcessLookupError, PermissionError):  # already gone
        os.killpg(pgid, sig)


def _describe(code: int) -> str:
    if code == 0:
        return "exited cleanly"
    if code < 0:
        return f"was killed by {signal.Signals(-code).name}"
    return f"died with exit code {code}"


def _ros2_exit(pid: int, code: int, command: list[str]) -> str:
    """A process's end in ros2 launch's words (a signal's name added: -11 is SIGSEGV)."""
    if code == 0:
        return f"process has finished cleanly [pid {pid}]"
    signal_name = f" ({signal.Signals(-code).name})" if code < 0 else ""
    return f"process has died [pid {pid}, exit code {code}{signal_name}, cmd '{' '.join(command)}']"


class GroupKeeper:
    """A helper process that kills the process groups the launcher leaves if it dies.

    The launcher tells it which process groups are alive through a pipe. When the pipe
    closes (the launcher exited, crashed or was SIGKILLed), it kills the groups still listed.
    """

    def __init__(self) -> None:
        read_end, self._write_end = os.pipe()
        self.pid = os.fork()  # before any thread exists, so forking without exec is safe
        if self.pid == 0:
            os.close(self._write_end)
            self._guard(read_end)
        os.close(read_end)

    @staticmethod
    def _guard(read_end: int) -> None:
        try:
            os.setsid()  # leave the terminal's process group: a Ctrl-C is for the launcher
            devnull = os.open(os.devnull, os.O_RDWR)
            for fd in (0, 1, 2):  # hold none of the launcher's output pipes open
                os.dup2(devnull, fd)
            groups: set[int] = set()
            with os.fdopen(read_end, "rb") as pipe:
                for line in pipe:
                    (groups.add if line.startswith(b"+") else groups.discard)(int(line[1:]))
            for pgid in groups:
                _kill_group(pgid, signal.SIGKILL)
        finally:
            os._exit(0)

    def _tell(self, message: str) -> None:
        with contextlib.suppress(OSError):  # the keeper is gone; PDEATHSIG still protects
            os.write(self._write_end, message.encode())

    def watch(self, pgid: int) -> None:
        self._tell(f"+{pgid}\n")

    def forget(self, pgid: int) -> None:
        self._tell(f"-{pgid}\n")

    def close(self) -> None:
        os.close(self._write_end)
        os.waitpid(self.pid, 0)


class LogSink:
    """A child's log file, written as its output comes. When the file cannot be written (the
    disk is full) it says so once, through ``say``, and the output goes on to the screen:
    an OSError here ended the thread that relays the child's output (``No space left on
    device`` in the pump), and nothing of that child reached the screen any more."""

    def __init__(self, path: Path, label: str, say: Callable[[str], None]) -> None:
        self.path, self.label, self.say = path, label, say
        self.file: IO[bytes] | None = None
        try:
            self.file = path.open("ab")
        except OSError as error:
            self._give_up(error)

    def write(self, raw: bytes) -> None:
        if self.file is None:
            return
        try:
            self.file.write(raw)
            self.file.flush()
        except OSError as error:
            self._give_up(error)

    _told: ClassVar[set[Path]] = set()  # the child's stdout and stderr share a file: say it once

    def _give_up(self, error: OSError) -> None:
        if self.file is not None:
            with contextlib.suppress(OSError):
                self.file.close()
        self.file = None
        if self.path in LogSink._told:
            return
        LogSink._told.add(self.path)
        self.say(
            f"cannot write {self.path} ({error.strerror or error}): {self.label}'s output "
            "is no longer logged (what goes to the screen still does)"
        )

    def close(self) -> None:
        if self.file is not None:
            with contextlib.suppress(OSError):
                self.file.close()


class Child:
    """One planned process and its current run."""

    def __init__(self, spec: ProcessSpec, log_dir: Path) -> None:
        self.spec = spec
        self.name = spec.label  # on the screen; ros2 launch's EXECUTABLE-N from its first start
        self.pid = 0
        self.log_path = log_dir / f"{spec.label.replace('/', '.')}.log"
        self.process: subprocess.Popen | None = None
        self.readers: list[threading.Thread] = []
        self.started_at = 0.0
        self.quick_failures = 0  # in a row
        self.restart_at: float | None = None
        self.stage = 0  # the last signal sent while shutting down
        self.deadline = 0.0


class Supervisor:
    def __init__(
        self,
        specs: list[ProcessSpec],
        log_dir: Path,
        debug: bool = False,
        steps: list[Step] | None = None,
        ros2: bool = False,
        warnings: list[str] | None = None,
        messages: list[str] | None = None,
    ) -> None:
        self.debug = debug
        self.ros2 = ros2  # speak as ros2 launch (see the module docstring)
        self.started = 0  # processes started so far: ros2 launch numbers them
        self.warnings, self.messages = warnings or [], messages or []
        self.children = [Child(spec, log_dir) for spec in specs]
        self.steps = steps or []
        self.pending: list[tuple[float, int, Child | Step, dict]] = []  # (due, order, what, event)
        self.order = 0
        self.lines: queue.Queue[tuple[int, str, str]] = queue.Queue()  # (index, stream, line)
        self.shutdown_reason = ""
        self.log_dir = log_dir
        self.launcher_pid = os.getpid()
        self.output_lock = threading.Lock()
        self.stop_signal: int | None = None
        self.hurry = False  # another signal arrived while shutting down
        self.abandoned = False  # the guardian was killed: kill everything, at once
        self.ending = False  # a required process exited, or a Shutdown event
        self.failed = False

    def say(self, text: str, level: str = "INFO", who: str = "launch") -> None:
        """One line of the launcher's own (``who``: a process's name says it of that process)."""
        if self.ros2:
            self.show(f"[{level}] [{who}]: {text}", sys.stdout)
        elif who == "launch":
            self.show(f"[launcher] {text}", sys.stdout)
        else:
            self.show(f"[launcher] {who} {text}", sys.stdout)

    def show(self, line: str, screen: IO[str]) -> None:
        # A closed terminal or pipe (launcher | head) must not stop the supervision.
        with self.output_lock, contextlib.suppress(OSError, ValueError):
            print(line, file=screen, flush=True)

    def run(self) -> int:
        """Start everything, watch until done or told to stop, shut down. The exit code."""
        handled = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
        previous = {sig: signal.signal(sig, self._on_signal) for sig in handled}
        # Orphaned descendants (a grandchild that called setsid) come to us, not to init.
        _libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
        self.adopted: set[int] = set()
        self.keeper = GroupKeeper()
        try:
            if self.ros2:
                self.say(f"All log files can be found below {self.log_dir}")
                self.say("Default logging verbosity is set to INFO")
                for warning in self.warnings:
                    self.say(warning, "WARNING")
                for message in self.messages:
                    self.say(message, who="launch.user")
            else:
                self.say(f"logging to {self.log_dir}")
            try:
                self.raise_event(None, None, {})  # what starts at once, and the first timers
                self.run_due()
                self.watch()
            except (OSError, subprocess.SubprocessError) as error:
                self.say(f"cannot start a process: {error}", "ERROR")
                self.failed = True
            self.on_shutdown()
            self.shutdown()
            self.stop_adopted()
        finally:
            self.keeper.close()
            for sig, handler in previous.items():
                signal.signal(sig, handler)
        if self.stop_signal is not None:
            return 128 + self.stop_signal  # 130 after Ctrl-C, like a shell
        return 1 if self.failed else 0

    # -- timers and events -----------------------------------------------------------------

    def raise_event(self, event: str | None, index: int | None, info: dict) -> None:
        """Schedule what waits for ``event`` of process ``index`` (None at the start)."""
        now = time.monotonic()
        waiting: list[Child | Step] = [*self.steps, *self.children]  # a message first
        for what in waiting:
            when = what.spec.when if isinstance(what, Child) else what.when
            if when.event != event or event == "shutdown":
                continue
            if event is not None and when.target is not None and when.target != index:
                continue
            self.order += 1
            self.pending.append((now + when.delay, self.order, what, info))

    def run_due(self) -> None:
        """Start the processes and do the steps whose time has come, in order."""
        now = time.monotonic()
        due = sorted(item for item in self.pending if item[0] <= now)
        for item in due:
            self.pending.remove(item)
        for _, _, what, info in due:
            if self.stop_signal is not None or self.ending:
                return  # no new process once told to stop: it would be stopped at once
            if isinstance(what, Child):
                if what.process is None and what.restart_at is None:  # not twice at once
                    self.start(what)
            else:
                self.do_step(what, info)

    def do_step(self, step: Step, info: dict) -> None:
        if step.kind == "log":
            self.say(step.text, who="launch.user")
        elif step.kind == "shutdown":
            if not self.ros2:  # ros2 launch's Shutdown event says nothing of its own
                self.say(f"shutting down: {step.text}")
            self.ending, self.shutdown_reason = True, step.text
        elif step.kind == "error":  # as ros2 launch's LaunchService reports what an action raised
            reason = f"Caught exception in launch (see debug for traceback): {step.text}"
            self.say(reason, "ERROR")
            self.ending, self.shutdown_reason, self.failed = True, reason, True
        elif step.call is not None:
            for result in step.call(info):  # a Python launch file's handler: logs and shutdowns
                self.do_step(result, info)

    def on_shutdown(self) -> None:
        """The launch shuts down (a signal, a Shutdown event, a required exit, or nothing is
        left running): the OnShutdown handlers' steps, once."""
        self.pending.clear()  # timers are cancelled
        if self.stop_signal is not None:
            reason = f"ctrl-c ({signal.Signals(self.stop_signal).name})"
            if self.ros2 and self.stop_signal == signal.SIGINT:  # ros2 launch's words
                self.say("user interrupted with ctrl-c (SIGINT)", "WARNING")
        else:
            reason = self.shutdown_reason or "idle"
        for step in self.steps:
            # A timer inside an OnShutdown handler is cancelled by the shutdown it waits in, as
            # ros2 launch's TimerAction cancels itself on Shutdown: only its undelayed steps run.
            if step.when.event == "shutdown" and step.kind != "shutdown" and not step.when.delay:
                self.do_step(step, {"reason": reason})

    def _on_signal(self, signum: int, _frame: object) -> None:
        if guardian.abandoned():  # its death sent this SIGTERM: end as abruptly as it did
            self.abandoned = self.hurry = True
        if self.stop_signal is None:
            self.stop_signal = signum
        else:
            self.hurry = True

    def _die_with_launcher(self) -> None:
        # Runs in the child between fork and exec. Python warns that preexec_fn may deadlock
        # when other threads hold locks at fork time (the output readers run meanwhile); this
        # one only makes a prctl call resolved before the fork, and takes no Python-level lock.
        _libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        _libc.signal(signal.SIGTTOU, 0)  # SIG_DFL again: the guardian made the launcher ignore it
        if os.getppid() != self.launcher_pid:  # the launcher died before prctl took effect
            os.kill(os.getpid(), signal.SIGKILL)

    def start(self, child: Child) -> None:
        spec = child.spec
        env = dict(os.environ)
        for name, value in spec.env.items():
            if value is None:
                env.pop(name, None)
            else:
                env[name] = value
        env["PYTHONUNBUFFERED"] = "1"  # output appears as it is written, not at exit
        if "PATH" not in spec.env:  # `ros2 ...` in an ExecuteProcess or <executable>
            env["PATH"] = program_path()
        env["ROS_LOG_DIR"] = str(self.log_dir)  # the nodes' own log files go here too
        apply_dds_defaults(env)
        apply_ament_defaults(env)  # a node that looks up a package finds what the launcher found
        child.process = subprocess.Popen(
            spec.command,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            env=env,
            cwd=spec.cwd,
            start_new_session=True,
            preexec_fn=self._die_with_launcher,
        )
        self.keeper.watch(child.process.pid)
        child.started_at, child.restart_at = time.monotonic(), None
        child.pid = child.process.pid
        if self.ros2 and child.name == spec.label:  # its first start: ros2 launch's name
            self.started += 1
            child.name = f"{spec.process_name}-{self.started}"
            child.log_path = child.log_path.with_name(f"{child.name}.log")  # the screen's name
        # As roslaunch: stderr (where ROS 2 logging writes) always reaches the screen,
        # stdout only with output="screen"; the log file gets both.
        to_screen = spec.output in ("screen", "both")
        child.readers = [
            self._reader(child, child.process.stdout, sys.stdout if to_screen else None, "stdout"),
            self._reader(child, child.process.stderr, sys.stderr, "stderr"),
        ]
        if self.ros2:
            self.say(f"process started with pid [{child.pid}]", who=child.name)
        else:
            self.say(f"started {spec.label} (pid {child.pid})")
        if self.debug:
            self.say(f"  command: {shlex.join(spec.command)}")
        info = {"pid": child.process.pid, "cmd": spec.command, "cwd": spec.cwd}
        self.raise_event("start", self.children.index(child), info)

    def _listened(self, child: Child, name: str) -> bool:
        index = self.children.index(child)
        return any(
            step.when.event == name and step.when.target in (None, index) for step in self.steps
        )

    def _reader(
        self, child: Child, stream: IO[bytes] | None, screen: IO[str] | None, name: str
    ) -> threading.Thread:
        log_path = child.log_path
        listened = self._listened(child, name)  # an OnProcessIO handler reads these lines
        index = self.children.index(child)

        def pump() -> None:
            assert stream is not None
            held: list[str] = []
            cut = False  # the rest of a line already cut on the screen
            log = LogSink(log_path, child.name, lambda text: self.say(text, "WARNING"))
            try:
                # readline(limit): a 200 MB line without a newline is read 64 KiB at a time.
                for raw in iter(lambda: stream.readline(MAX_LINE_BYTES), b""):
                    log.write(raw)
                    if listened and raw.strip():  # an OnProcessIO handler: not blank lines
                        self.lines.put((index, name, raw.decode(errors="replace")))
                    if screen is None:
                        continue
                    complete = raw.endswith(b"\n")
                    if cut:
                        cut = not complete
                        continue
                    line = raw.decode(errors="replace").rstrip("\n")
                    if not complete:
                        cut = True
                        line += f" [line cut at {MAX_LINE_BYTES} bytes; whole in {log_path}]"
                    self._relay(child, line, screen, held)
                if held and screen is not None:
                    self._flush_held(child, screen, held)
            finally:
                log.close()
            stream.close()

        thread = threading.Thread(target=pump, daemon=True)
        thread.start()
        return thread

    def _relay(self, child: Child, line: str, screen: IO[str], held: list[str]) -> None:
        """Show a line; hold back a traceback of a child we are stopping (see _flush_held)."""
        # (A KeyboardInterrupt raised in C code has no traceback: its line comes first, then
        # the error it caused, such as rclpy's "ImportError: initialization failed".)
        starts = ("Traceback (most recent call last):", "Fatal Python error:", "KeyboardInterrupt")
        if held or (child.stage and line.startswith(starts)):
            held.append(line)
            if len(held) >= MAX_TRACEBACK_LINES:
                self._flush_held(child, screen, held)
            return
        self.show(shown_line(child.spec.output_format, child.name, line), screen)

    def _flush_held(self, child: Child, screen: IO[str], held: list[str]) -> None:
        """A child that gets the launcher's SIGINT without a handler for it (still starting or
        importing, or a running node whose `main` does not catch KeyboardInterrupt, as the
        official Jazzy tutorials' nodes) prints a KeyboardInterrupt traceback. That is the
        expected end of a stop, not an error: one line on the screen, the traceback in the log
        file. Any other traceback is shown whole."""
        label = child.name
        if any(line.startswith("KeyboardInterrupt") for line in held):
            self.show(f"[{label}] stopped (its traceback is in the log)", screen)
        else:
            for line in held:
                self.show(f"[{label}] {line}", screen)
        held.clear()

    def _find_adopted(self) -> set[int]:
        """Processes the kernel gave us as subreaper: our children that we did not start."""
        ours = {c.process.pid for c in self.children if c.process is not None}
        ours.add(self.keeper.pid)
        me, found = os.getpid(), set()
        for entry in os.scandir("/proc"):
            if not entry.name.isdigit() or int(entry.name) in ours:
                continue
            try:
                with open(f"/proc/{entry.name}/stat", "rb") as stat:
                    fields = stat.read().rsplit(b")", 1)[1].split()
            except (OSError, IndexError):
                continue  # gone meanwhile
            if int(fields[1]) == me:
                found.add(int(entry.name))
        return found

    def _reap_adopted(self) -> None:
        for pid in list(self.adopted):
            try:
                done, _ = os.waitpid(pid, os.WNOHANG)
            except ChildProcessError:
                done = pid
            if done:
                self.adopted.discard(pid)
                self.keeper.forget(pid)

    def note_adopted(self) -> None:
        """Record newly adopted processes (the keeper kills them if we die); reap exited ones."""
        for pid in self._find_adopted() - self.adopted:
            self.adopted.add(pid)
            self.keeper.watch(pid)  # a setsid process leads its own group: killpg reaches it
        self._reap_adopted()

    def stop_adopted(self) -> None:
        """Stop what escaped the process groups and was adopted: SIGTERM, later SIGKILL."""
        deadline, sig, told = time.monotonic() + ADOPTED_STOP_SECONDS, signal.SIGTERM, False
        while True:
            self.note_adopted()
            if not self.adopted:
                return
            if not told:
                self.say(f"stopping {len(self.adopted)} process(es) that left their group")
                told = True
            if time.monotonic() >= deadline or self.hurry or self.abandoned:
                sig = signal.SIGKILL
            if time.monotonic() >= deadline + ADOPTED_STOP_SECONDS:  # unkillable (state D)
                self.say(f"still running after SIGKILL: pid(s) {sorted(self.adopted)}", "ERROR")
                return
            for pid in self.adopted:
                with contextlib.suppress(ProcessLookupError):
                    os.kill(pid, sig)
            time.sleep(POLL_SECONDS)

    def reap(self, child: Child) -> int:
        assert child.process is not None
        pid = child.process.pid
        _kill_group(pid, signal.SIGKILL)  # what it left running in its group
        code = child.process.wait()
        self.keeper.forget(pid)
        for reader in child.readers:
            reader.join(timeout=2.0)  # print its last lines before saying it exited
        child.process = None
        return code

    def watch(self) -> None:
        last_sweep = 0.0
        while self.stop_signal is None and not self.ending:
            now = time.monotonic()
            if now - last_sweep >= 1.0:  # reap adopted processes that ended on their own
                self.note_adopted()
                last_sweep = now
            for child in self.children:
                if child.process is not None and _exited(child.process.pid):
                    self.on_exit(child, self.reap(child), now)
                elif child.restart_at is not None and now >= child.restart_at:
                    if self.stop_signal is not None:
                        break  # a signal came during this round: stop, don't respawn
                    self.start(child)
            while not self.lines.empty():
                index, name, line = self.lines.get()
                self.raise_event(name, index, {"text": line, "pid": None})
            self.run_due()
            idle = all(c.process is None and c.restart_at is None for c in self.children)
            if idle and not self.pending and self.lines.empty():
                return
            time.sleep(POLL_SECONDS)

    def on_exit(self, child: Child, code: int, now: float) -> None:
        self._on_exit(child, code, now)
        self.raise_event("exit", self.children.index(child), {"returncode": code})

    def exited(self, child: Child, code: int, then: str = "") -> None:
        """Say that a process ended, and (``then``) what follows from it."""
        if not self.ros2:
            self.say(f"{child.spec.label} {_describe(code)}{then}")
            return
        text = _ros2_exit(child.pid, code, child.spec.command)
        self.say(text + (then or ("." if code else "")), "ERROR" if code else "INFO", child.name)

    def _on_exit(self, child: Child, code: int, now: float) -> None:
        spec = child.spec
        if spec.required:
            self.exited(child, code, "; it is required, so the launch ends")
            self.failed |= code != 0
            self.ending = True
        elif spec.respawn:
            ran_long = now - child.started_at >= STABLE_RUN_SECONDS
            child.quick_failures = 0 if ran_long else child.quick_failures + 1
            limit = spec.respawn_max_retries
            if 0 <= limit < child.quick_failures:
                then = f"; not respawning it after {limit} quick restarts in a row"
                self.exited(child, code, then)
                self.failed = True
                return
            delay = spec.respawn_delay
            if child.quick_failures:  # back off so a crashing process cannot spin the CPU
                backoff = BACKOFF_FIRST_SECONDS * 2 ** (child.quick_failures - 1)
                delay += min(backoff, BACKOFF_MAX_SECONDS)
            self.exited(child, code, f"; respawning in {delay:.1f} s")
            child.restart_at = now + delay
        else:
            self.exited(child, code)
            self.failed |= code != 0

    def shutdown(self) -> None:
        for child in self.children:
            child.restart_at = None
        alive = [child for child in self.children if child.process is not None]
        if alive and not self.ros2:  # ros2 launch prints each one's end instead (below)
            self.say(f"stopping {len(alive)} process(es)")
        for child in alive:
            self._escalate(child)
        count = len(alive)
        while alive:
            now = time.monotonic()
            for child in list(alive):
                assert child.process is not None
                if _exited(child.process.pid):
                    code = self.reap(child)
                    alive.remove(child)
                    if self.ros2:  # as ros2 launch: each one's end, as it stops
                        self.exited(child, code)
                elif now >= child.deadline or self.hurry:
                    self._escalate(child)
            self.hurry = False
            time.sleep(POLL_SECONDS)
        if count and not self.ros2:
            self.say(f"all {count} process(es) stopped")

    def _say_escalation(self, child: Child, then: signal.Signals, seconds: str) -> None:
        """A child still running after its signal: ros2 launch's two lines (its
        execute_local.py: the error with the seconds since the SIGINT, then 'sending signal'),
        or the launcher's own."""
        sent = signal.Signals(child.stage).name
        if self.ros2:
            self.say(
                f"process[{child.name}] failed to terminate '{seconds}' seconds after "
                f"receiving '{sent}', escalating to '{then.name}'",
                "ERROR",
                child.name,
            )
            self.say(f"sending signal '{then.name}' to process[{child.name}]", who=child.name)
        else:
            self.say(f"still running after {sent}: sending {then.name}", "WARNING", child.name)

    def _escalate(self, child: Child) -> None:
        """Send the next signal of SIGINT -> SIGTERM -> SIGKILL to the child's group."""
        assert child.process is not None
        spec, now = child.spec, time.monotonic()
        if self.abandoned:
            child.stage, child.deadline = signal.SIGKILL, float("inf")
        elif child.stage == 0:
            child.stage, child.deadline = signal.SIGINT, now + spec.sigterm_timeout
        elif child.stage == signal.SIGINT:
            self._say_escalation(child, signal.SIGTERM, f"{spec.sigterm_timeout:g}")
            child.stage, child.deadline = signal.SIGTERM, now + spec.sigkill_timeout
        else:
            if child.stage == signal.SIGTERM:  # ros2 launch: float(sigterm) + float(sigkill)
                after = str(float(spec.sigterm_timeout) + float(spec.sigkill_timeout))
                self._say_escalation(child, signal.SIGKILL, after)
            child.stage, child.deadline = signal.SIGKILL, float("inf")
        _kill_group(child.process.pid, child.stage)
