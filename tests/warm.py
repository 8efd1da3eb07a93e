"""Warm starts: the tests' processes of this project, forked from one that has imported it.

The suite starts about 500 processes of this project (`rostopic list`, `rosbag info`, a
lesson's server, ...). A cold start costs about 0.5 s of CPU, of which 0.35 s is Python's own
start and the imports of rclpy, numpy and the tools; on a 2-core machine that alone was half of
the suite's time. This module's server (one per pytest process, ``python tests/warm.py
SOCKET``) imports all that once and then forks a child per command. The child makes itself
what a fresh ``python -m MODULE ARGS`` or ``python SCRIPT ARGS`` would be (argv, environment,
working directory, standard streams, signal mask and handlers, session) and runs the command
the way Python runs it (runpy), to Python's own end: exit status, uncaught exceptions, Ctrl-C
(the process then dies by SIGINT) and atexit are the interpreter's.

What stays real: every command is a process of its own (its own pid, DDS participant, exit
status and streams), run from its entry point with its arguments, talking to the others
through real DDS. What differs from a cold start: the modules were imported before the
command's environment was set, so only commands run with the test session's own environment
come here (``Starter.eligible``; any other environment starts cold), and the process's parent
is this server. Tests where the start itself is the point (Ctrl-C during start-up, a console
script's first line, the launcher's guardian) start cold (``cold=True`` in tests/helpers.py).

The protocol, on a Unix SOCK_SEQPACKET socket (one message each): the client sends the request
(JSON) with its three standard streams' descriptors; the server answers the child's pid, then,
when the child has ended, its wait status (as ``os.waitpid`` gives it).
"""

from __future__ import annotations

import contextlib
import gc
import json
import os
import select
import signal
import socket
import subprocess
import sys
import threading
from collections.abc import Mapping, Sequence

# Imported once here, before any fork: Python, rclpy (and numpy, through the messages it
# uses), every tool and lesson, and the type supports every node loads.
PRELOAD = (
    "rclpy",
    "rclpy.action",
    "ros2cmd.cli",
    "ros2cmd.ros1.rosbag",
    "ros2cmd.ros1.rosmsg",
    "ros2cmd.ros1.rosnode",
    "ros2cmd.ros1.rosparam",
    "ros2cmd.ros1.rospack",
    "ros2cmd.ros1.rosservice",
    "ros2cmd.ros1.rostopic",
    "ros2cmd.ros1.rqt",
    "ros_tutorials_topic",
    "ros_tutorials_service",
    "ros_tutorials_parameter",
    "ros_tutorials_action",
    "ros_tutorials_turtlesim",
)
# The packages whose commands start warm. Not the launcher: it imports no rclpy (little to
# gain), the tests of its guardian find its processes by their initial environment
# (/proc/PID/environ, which a fork keeps), and a launcher forked from here can die by SIGSEGV
# at exit (its guardian forks again, with the ROS libraries loaded).
PROJECT = frozenset(name.split(".")[0] for name in PRELOAD if not name.startswith("rclpy"))
ENDED = b"ended "


# --- the server ---------------------------------------------------------------------------


def _preload() -> dict[str, str]:
    """Import what every command needs; return the variables those imports put into the
    environment (a module's os.environ.setdefault), which each child gets again."""
    import importlib
    import pkgutil

    before = dict(os.environ)
    for name in PRELOAD:
        module = importlib.import_module(name)
        if name.startswith("ros_tutorials_"):  # a lesson package: each node's module
            for info in pkgutil.iter_modules(module.__path__, f"{name}."):
                importlib.import_module(info.name)
    import rcl_interfaces.msg
    import type_description_interfaces.srv
    from rclpy.type_support import check_for_type_support

    for kind in (rcl_interfaces.msg.ParameterEvent, rcl_interfaces.msg.Log):
        check_for_type_support(kind)
    check_for_type_support(type_description_interfaces.srv.GetTypeDescription)
    return {name: value for name, value in os.environ.items() if before.get(name) != value}


def serve(path: str) -> tuple[dict, list[int]]:
    """Answer requests until killed; returns only in a child, with its request."""
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_SEQPACKET)
    listener.bind(path)
    listener.listen(64)
    wake_read, wake_write = os.pipe()
    os.set_blocking(wake_read, False)
    os.set_blocking(wake_write, False)
    signal.set_wakeup_fd(wake_write)
    signal.signal(signal.SIGCHLD, lambda *_: None)  # wakes select() through the pipe
    children: dict[int, socket.socket] = {}
    print("ready", flush=True)
    while True:
        readable = select.select([listener, wake_read], [], [])[0]
        if wake_read in readable:
            while True:
                try:
                    if not os.read(wake_read, 512):
                        break
                except BlockingIOError:
                    break
            _reap(children)
        if listener not in readable:
            continue
        connection, _ = listener.accept()
        try:
            message, fds, _, _ = socket.recv_fds(connection, 1 << 20, 3)
            request = json.loads(message)
        except (OSError, ValueError):
            connection.close()
            continue
        pid = os.fork()
        if pid == 0:
            signal.set_wakeup_fd(-1)
            signal.signal(signal.SIGCHLD, signal.SIG_DFL)
            for handle in (listener, connection, *children.values()):
                handle.close()
            os.close(wake_read)
            os.close(wake_write)
            return request, fds
        for fd in fds:
            os.close(fd)
        children[pid] = connection
        with contextlib.suppress(OSError):
            connection.send(str(pid).encode())


def _reap(children: dict[int, socket.socket]) -> None:
    while children:
        try:
            pid, status = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return
        connection = children.pop(pid, None)
        if connection is not None:
            with contextlib.suppress(OSError):  # the test may have stopped waiting
                connection.send(ENDED + str(status).encode())
            connection.close()


def become(request: dict, fds: list[int], imported: dict[str, str]) -> None:
    """In the child: the process state a fresh interpreter running the command would have."""
    for target, fd in enumerate(fds):
        os.dup2(fd, target)  # sys.stdin/stdout/stderr keep their objects, on the new files
    for fd in fds:
        if fd > 2:
            os.close(fd)
    if request["new_session"]:
        os.setsid()
    os.chdir(request["cwd"])
    os.environ.clear()
    os.environ.update(request["env"])
    for name, value in imported.items():
        os.environ.setdefault(name, value)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.pthread_sigmask(signal.SIG_SETMASK, ())
    import random

    random.seed()  # every child would otherwise draw the same numbers
    argv = request["argv"]
    sys.orig_argv = [sys.executable, *argv]


def run(argv: Sequence[str]) -> None:
    """Run the command as `python -m MODULE ...` or `python SCRIPT ...` would."""
    import runpy

    if argv[0] == "-m":
        sys.argv = [argv[1], *argv[2:]]
        sys.path[0] = os.getcwd()
        sys.modules.pop(argv[1], None)  # imported by _preload: run afresh, as __main__
        runpy.run_module(argv[1], run_name="__main__", alter_sys=True)
    else:
        sys.argv = list(argv)
        sys.path[0] = os.path.dirname(os.path.abspath(argv[0]))
        runpy.run_path(argv[0], run_name="__main__")


# --- the client ---------------------------------------------------------------------------


def _package(argv: Sequence[str]) -> str | None:
    """The package of this project a command runs: `-m PACKAGE.MODULE`, or a console script
    of this environment (`from PACKAGE.MODULE import main`)."""
    if argv[0] == "-m":
        return argv[1].split(".")[0]
    if os.path.dirname(argv[0]) != os.path.dirname(sys.executable):
        return None
    try:
        with open(argv[0], "rb") as script:
            head = script.read(1024)
    except OSError:
        return None
    if not head.startswith(b"#!"):
        return None  # a program, not a console script
    for line in head.splitlines():
        if line.startswith(b"from "):
            return line.split()[1].split(b".")[0].decode()
    return None


class WarmProcess:
    """A command run by the server: what the tests use of subprocess.Popen."""

    def __init__(self, path: str, request: dict, streams: Sequence[int]) -> None:
        self.args = request["argv"]
        self._connection = socket.socket(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        self._connection.connect(path)
        socket.send_fds(self._connection, [json.dumps(request).encode()], list(streams))
        self.pid = int(self._connection.recv(64))
        self.returncode: int | None = None

    def poll(self) -> int | None:
        if self.returncode is None:
            self._connection.setblocking(False)
            with contextlib.suppress(BlockingIOError):
                self._ended(self._connection.recv(64))
        return self.returncode

    def wait(self, timeout: float | None = None) -> int:
        if self.returncode is None:
            self._connection.settimeout(timeout)
            try:
                self._ended(self._connection.recv(64))
            except TimeoutError:
                raise subprocess.TimeoutExpired(self.args, timeout) from None
        assert self.returncode is not None
        return self.returncode

    def _ended(self, message: bytes) -> None:
        if not message.startswith(ENDED):
            raise RuntimeError(f"warm-start server gone while {self.args} ran")
        self.returncode = os.waitstatus_to_exitcode(int(message[len(ENDED) :]))
        self._connection.close()

    def send_signal(self, sig: int) -> None:
        if self.poll() is None:
            os.kill(self.pid, sig)

    def kill(self) -> None:
        self.send_signal(signal.SIGKILL)


class Starter:
    """The server of one pytest process, started with that process's environment."""

    # Variables no module of this project reads when imported, only when it runs: a command
    # with other values of these still starts warm (pytest names each test; turtlesim, the
    # GUI stand-ins and rqt_logger_level look for a display and the log folder at run time, and
    # SDL sets SDL_VIDEODRIVER in the test's own process when an in-process turtlesim draws).
    RUN_TIME_ONLY = (
        "PYTEST_CURRENT_TEST",
        "PYTHONUNBUFFERED",
        "DISPLAY",
        "WAYLAND_DISPLAY",
        "SDL_VIDEODRIVER",
        "ROS_LOG_DIR",
    )

    def __init__(self, folder: str) -> None:
        self.path = os.path.join(folder, "warm.sock")
        self.base = self._import_time(os.environ)
        # numpy's OpenBLAS would start a thread per core at import: none before a fork.
        server_env = {**os.environ, "PYTHONUNBUFFERED": "1", "OPENBLAS_NUM_THREADS": "1"}
        self._server = subprocess.Popen(
            [sys.executable, __file__, self.path],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            env=server_env,
        )
        self._ready: bool | None = None
        # Commands started together (helpers.at_once) ask at once: one reads the line.
        self._ready_lock = threading.Lock()

    @classmethod
    def _import_time(cls, env: Mapping[str, str]) -> dict[str, str]:
        return {name: value for name, value in env.items() if name not in cls.RUN_TIME_ONLY}

    def ready(self) -> bool:
        with self._ready_lock:
            if self._ready is None:
                assert self._server.stdout is not None
                self._ready = self._server.stdout.readline() == b"ready\n"
            return self._ready

    def eligible(self, argv: Sequence[str], env: Mapping[str, str]) -> bool:
        """A command of this project, run in the environment the server imported it in (see
        the docstring)."""
        if self._import_time(env) != self.base:
            return False
        return _package(argv) in PROJECT and self.ready()

    def start(
        self,
        argv: Sequence[str],
        env: Mapping[str, str],
        streams: Sequence[int],
        cwd: str | None,
        new_session: bool,
    ) -> WarmProcess:
        request = {
            "argv": list(argv),
            "env": dict(env),
            "cwd": cwd or os.getcwd(),
            "new_session": new_session,
        }
        return WarmProcess(self.path, request, streams)

    def stop(self) -> None:
        self._server.kill()
        self._server.wait()


if __name__ == "__main__":
    imported = _preload()
    # What is imported now stays out of the garbage collector's sight (Python's advice for
    # fork() without exec()). Otherwise every child's collections, and the last one at its
    # exit, write to every imported object and so copy the pages they share with this
    # server: an `interface show` cost 0.17 CPU-s instead of 0.07. The child still ends as
    # Python ends (atexit, module teardown); only cycles among these objects are not freed.
    gc.freeze()
    request, fds = serve(sys.argv[1])
    become(request, fds, imported)
    del request, fds, imported
    run(sys.orig_argv[1:])
