"""Ctrl-C from the first instant of a command: no traceback, exit status 130.

Python turns SIGINT into KeyboardInterrupt from early in its own start-up, long before a
program can catch it: while ``site`` runs the ``.pth`` files (the ROS wheels' bootstrapper
re-executes the interpreter from one, and setuptools' editable finder imports pathlib from
another), a KeyboardInterrupt is fatal to the interpreter ("Fatal Python error:
init_import_site" and a traceback); while a command imports rclpy and its own modules, it is
an uncaught KeyboardInterrupt with a traceback. This module closes both windows for this
project's commands (``is_project_command``), in two steps:

- ``00_ros_tutorials_ctrl_c.pth`` (written by ``make setup``; the first ``.pth`` file ``site``
  reads, before the bootstrapper's re-exec) blocks SIGINT, and ``hold()`` keeps it blocked
  for a command of this project (unblocks it for any other program). A Ctrl-C now waits,
  pending; the mask and the pending signal survive the re-exec, so the interpreter that runs
  the command starts with it blocked too.
- ``release()`` runs from every package's ``__init__.py`` (the first code of this project a
  command runs): it makes an uncaught KeyboardInterrupt leave without a traceback (and the
  errors a Ctrl-C causes while rclpy loads or a node is created: ``interrupted``), then
  unblocks SIGINT. A pending Ctrl-C is delivered at once and ends the command like any later
  one before the command handles Ctrl-C itself: no output, killed by SIGINT (a shell's 130).

Nothing here installs a signal handler, so rclpy's handler, installed by rclpy.init, chains to
Python's own as before. Other programs run with this environment's Python (pytest, pip) are
left alone.

Python's own start, from where it installs its SIGINT handler to the first ``.pth`` file,
comes before any code of an environment can run. ``make setup`` therefore also starts this
project's console scripts through ``env --block-signal=INT`` (``install``), and the launcher
and rosrun start a command of this project with SIGINT blocked (``starts_project_command``,
``block_sigint``). Not covered: ``python -m PACKAGE`` typed by hand, in those milliseconds.
"""

from __future__ import annotations

import _signal  # the C module: ``signal`` imports enum, too slow for every start of Python
import _thread
import os
import sys

PACKAGES = frozenset(
    {
        "launch",  # the launch API Python launch files import (launcher/python_files.py)
        "launch_ros",
        "launch_xml",
        "launch_yaml",
        "launcher",
        "ros2cmd",
        "ros_tutorials_action",
        "ros_tutorials_common",
        "ros_tutorials_demo_nodes",
        "ros_tutorials_parameter",
        "ros_tutorials_service",
        "ros_tutorials_topic",
        "ros_tutorials_turtlesim",
        "ros_tutorials_web",
    }
)
PTH_NAME = "00_ros_tutorials_ctrl_c.pth"  # sorted before every other .pth file
OPTIONS_WITH_VALUE = frozenset({"-W", "-X"})
_SIGINT = {_signal.SIGINT}
# How rclpy and rcl refuse to go on once rclpy's signal handler has shut the context down.
STOPPED_ROS = frozenset({"ExternalShutdownException", "NotInitializedException"})
SHUT_DOWN = (
    "context is not valid",  # rcl's two wordings for a context that was shut down ...
    "context is invalid",
    # ... and rclpy.try_shutdown() after Ctrl-C, when rclpy's signal handler thread shut the
    # context down between try_shutdown's check and its own rcl_shutdown (seen under load
    # in `make run`: a traceback from one of union.launch's publishers).
    "rcl_shutdown already called",
)


def _module_is_ours(module: str) -> bool:
    return module.split(".", 1)[0] in PACKAGES


def _script_is_ours(path: str) -> bool:
    """A file of this project (``python ros_tutorials_topic/talker.py``), or a console script
    of this environment whose wrapper imports this project (``from ros2cmd.ros1 import ...``)."""
    folder = os.path.dirname(os.path.abspath(path))
    if os.path.basename(folder) in PACKAGES:
        return True
    if folder != os.path.join(sys.prefix, "bin"):
        return False
    try:
        with open(path, "rb") as script:
            head = script.read(1024)
    except OSError:
        return False
    if not head.startswith(b"#!"):
        return False
    for line in head.splitlines():
        if line.startswith(b"from ") or line.startswith(b"import "):
            module = line.split()[1].decode("ascii", "replace")
            if module != "sys":  # pip's wrapper imports sys first
                return _module_is_ours(module)
    return False


def is_project_command(argv: list[str]) -> bool:
    """Whether a Python command line (``sys.orig_argv``) runs a command of this project: a
    console script of this environment, ``python -m PACKAGE...`` or a file in a package."""
    args = iter(argv[1:])
    for arg in args:
        if arg == "-m":
            return _module_is_ours(next(args, ""))
        if arg.startswith("-m"):
            return _module_is_ours(arg[2:])
        if arg == "-" or arg.startswith("-c"):
            return False
        if arg in OPTIONS_WITH_VALUE:
            next(args, None)
        elif not arg.startswith("-"):
            return _script_is_ours(arg)
    return False


def hold() -> None:
    """From the .pth file, which has just blocked SIGINT: keep it blocked if this interpreter
    runs a command of this project, otherwise unblock it again."""
    if not is_project_command(sys.orig_argv):
        _signal.pthread_sigmask(_signal.SIG_UNBLOCK, _SIGINT)


# Set by a SIGINT handler of this project (ros_tutorials_common/ros/node_main.py) when
# Ctrl-C raises KeyboardInterrupt, and when rclpy's own handler had shut ROS down first (the
# program then ends through ExternalShutdownException even without the KeyboardInterrupt).
pressed = False
ros_stopped = False
terminated = False  # a SIGTERM came (node_main.py): the program ends by it, not by SIGINT
# A KeyboardInterrupt raised in Python code that rclpy's C++ calls while it converts a value
# (a message's __init__ inside take_message) comes out of pybind11 as this RuntimeError, the
# KeyboardInterrupt gone (seen once: turtlesim's mimic stopped by Ctrl-C as a pose arrived).
CONVERSION_FAILED = "Unable to convert call argument"


def interrupted(error: BaseException | None) -> bool:
    """Whether an uncaught exception is how a Ctrl-C (or another stop) while starting shows:
    a KeyboardInterrupt, an error it caused (a C extension's "ImportError: initialization
    failed"), or ROS refusing to go on in the context that rclpy's signal handler has just
    shut down (a lesson's node created while Ctrl-C arrives, before rclpy.spin)."""
    seen = set()
    while error is not None and id(error) not in seen:
        seen.add(id(error))
        if isinstance(error, KeyboardInterrupt):
            return True
        name, text = type(error).__name__, str(error)
        if name in STOPPED_ROS or (name == "RCLError" and any(s in text for s in SHUT_DOWN)):
            return True
        if pressed and name == "RuntimeError" and text.startswith(CONVERSION_FAILED):
            return True
        error = error.__cause__ or error.__context__
    return False


def _end_as_interrupted() -> None:
    """End now, killed by SIGINT like an uncaught KeyboardInterrupt (a shell's status 130),
    or by SIGTERM (143) if that is what stopped the program."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except Exception:
            pass
    number = _signal.SIGTERM if terminated and not pressed else _signal.SIGINT
    _signal.signal(number, _signal.SIG_DFL)
    _signal.pthread_sigmask(_signal.SIG_UNBLOCK, {number})
    os.kill(os.getpid(), number)
    os._exit(128 + number)


def _quiet_excepthook(kind, value, traceback) -> None:
    try:
        if issubclass(kind, KeyboardInterrupt):
            return  # nothing to say; Python then ends the process by SIGINT (status 130)
        if interrupted(value):
            _end_as_interrupted()
    except KeyboardInterrupt:  # a second Ctrl-C meanwhile
        _end_as_interrupted()
    _previous_excepthook(kind, value, traceback)


def _quiet_unraisablehook(unraisable) -> None:
    try:
        if isinstance(unraisable.exc_value, KeyboardInterrupt):
            _quiet_keyboard_interrupt()
            return
    except KeyboardInterrupt:  # one more Ctrl-C while this hook ran
        _quiet_keyboard_interrupt()
        return
    if not cut_short(unraisable):
        _previous_unraisablehook(unraisable)


def _quiet_keyboard_interrupt() -> None:
    """A KeyboardInterrupt Python could not raise: on the way out (atexit, module teardown)
    it is the exit already under way; while the program runs, it came while a __del__ ran
    (rclpy's Future and Task have one, and the executor drops one per callback), and it
    would be lost: the command would run on (`rostopic echo` ignored a Ctrl-C for 30 s under
    load). Delivered again, a moment later, from a thread: raised from here
    (signal.raise_signal, interrupt_main) it would only end this hook."""
    if _still_running() and not ros_stopped:
        _deliver_again()  # not where ROS is down: that program is ending already


def _deliver_again() -> None:
    try:  # a bare thread: threading's would wait here for it to start, and be interrupted
        _thread.start_new_thread(_interrupt_main_soon, ())
    except KeyboardInterrupt:  # delivered while this hook still ran (a busy machine)
        _thread.start_new_thread(_interrupt_main_soon, ())


def _interrupt_main_soon() -> None:
    import time

    time.sleep(0.01)  # the hook has returned by then, and the program's code runs
    _thread.interrupt_main(_signal.SIGINT)


def _still_running() -> bool:
    """Whether the program still runs: not yet in Python's shutdown (which marks the main
    thread stopped before the atexit callbacks run)."""
    threading = sys.modules.get("threading")
    return not sys.is_finalizing() and (threading is None or threading.main_thread().is_alive())


def cut_short(unraisable) -> bool:
    """An rclpy object's __del__ failing on an attribute that its __init__ sets: a Ctrl-C
    raised inside that __init__. Seen after a Ctrl-C had ended a command as it should: for a
    Future or Task (the executor makes one per callback; "Exception ignored in: <function
    Future.__del__ ...> AttributeError: ... '_exception'", after `rostopic echo`), and for the
    executor rclpy.spin makes and its SignalHandlerGuardCondition (a server stopped as it
    started spinning). rclpy's slip, not the command's."""
    where = unraisable.object
    return (
        isinstance(unraisable.exc_value, AttributeError)
        and getattr(where, "__module__", "").startswith("rclpy.")
        and getattr(where, "__name__", "") == "__del__"
    )


_previous_excepthook = sys.excepthook
_previous_unraisablehook = sys.unraisablehook


def release() -> None:
    """From a package's __init__: an uncaught KeyboardInterrupt ends this project's command
    without a traceback, and SIGINT (held since start-up) is delivered from now on."""
    global _previous_excepthook, _previous_unraisablehook
    if sys.excepthook is _quiet_excepthook or not is_project_command(sys.orig_argv):
        return
    _previous_excepthook, sys.excepthook = sys.excepthook, _quiet_excepthook
    _previous_unraisablehook, sys.unraisablehook = sys.unraisablehook, _quiet_unraisablehook
    _signal.pthread_sigmask(_signal.SIG_UNBLOCK, _SIGINT)  # a pending Ctrl-C raises here


def starts_project_command(command: list[str]) -> bool:
    """Whether a command line (a child's, or what rosrun executes) runs a command of this
    project: one of its console scripts, or Python running one (``is_project_command``)."""
    if not command:
        return False
    if _script_is_ours(command[0]) and os.path.dirname(command[0]):
        return True
    return os.path.basename(command[0]).startswith("python") and is_project_command(command)


def block_sigint() -> None:
    """Block SIGINT in this thread (before starting or executing a command of this project,
    whose release() unblocks it; a child started by fork inherits the mask)."""
    _signal.pthread_sigmask(_signal.SIG_BLOCK, _SIGINT)


def unblock_sigint() -> None:
    _signal.pthread_sigmask(_signal.SIG_UNBLOCK, _SIGINT)


def pth_line() -> str:
    """The line of the .pth file: block SIGINT at once, then run this file's hold() (this
    project is not importable yet: the editable install's finder comes later). The file's
    code comes from its cached .pyc, as an import would."""
    path = os.path.abspath(__file__)
    return (
        "import _signal; _signal.pthread_sigmask(_signal.SIG_BLOCK, {_signal.SIGINT}); "
        "import _frozen_importlib_external as _ros_tutorials_loader; "
        f"exec(_ros_tutorials_loader.SourceFileLoader('ros_tutorials_common.ctrl_c', {path!r})"
        ".get_code(None), _ros_tutorials_ctrl_c := {'__name__': 'ros_tutorials_ctrl_c_hold'}); "
        "_ros_tutorials_ctrl_c['hold']()\n"
    )


ENV = "/usr/bin/env"
SHEBANG_PREFIX = "#!" + ENV + " -S --block-signal=INT "
MAX_SHEBANG = 250  # Linux reads the first 256 bytes of a script for its #! line


def _env_blocks_signals() -> bool:
    import subprocess

    try:
        return subprocess.run([ENV, "--block-signal=INT", "true"], check=False).returncode == 0
    except OSError:
        return False


def install() -> list[str]:
    """``make setup``: write the .pth file into this environment's site-packages, and start
    this project's console scripts through ``env --block-signal=INT`` (GNU coreutils), so that
    SIGINT is blocked even before Python starts. What it did, one line each."""
    import py_compile
    import sysconfig

    # Its .pyc, which the .pth line loads, even where PYTHONDONTWRITEBYTECODE keeps Python
    # from writing one: compiling the file at every start of Python would cost milliseconds.
    py_compile.compile(os.path.abspath(__file__), doraise=True)
    done = []
    pth = os.path.join(sysconfig.get_paths()["purelib"], PTH_NAME)
    with open(pth, "w", encoding="utf-8") as file:
        file.write(pth_line())
    done.append(f"wrote {pth}")
    bin_dir = os.path.join(sys.prefix, "bin")
    if not _env_blocks_signals():
        return [*done, f"{ENV} has no --block-signal: console scripts left as they are"]
    changed = 0
    for entry in os.scandir(bin_dir):
        if not entry.is_file() or not _script_is_ours(entry.path):
            continue
        with open(entry.path, encoding="utf-8") as file:
            first, rest = file.readline(), file.read()
        interpreter = first[2:].strip()
        plain = not any(c in interpreter for c in " \t\\$'\"#")  # nothing env -S would parse
        if first.startswith(SHEBANG_PREFIX) or not first.startswith("#!/") or not plain:
            continue  # done before, or not pip's plain "#!/path/to/python" line
        line = SHEBANG_PREFIX + interpreter
        if len(line) > MAX_SHEBANG:
            continue
        with open(entry.path, "w", encoding="utf-8") as file:
            file.write(line + "\n" + rest)
        changed += 1
    return [*done, f"{changed} console scripts of this project now start with SIGINT blocked"]
