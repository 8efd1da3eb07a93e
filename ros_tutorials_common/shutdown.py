"""How a program of this project ends: on Ctrl-C, on SIGTERM, and when its output cannot be
written. The one design for the tools (``ros2``, the ROS 1 spellings, rosbag, rosrun, the
launcher, view_frames), the toolkit's nodes (tf2_echo, static_transform_publisher, tf2_monitor,
robot_state_publisher, joint_state_publisher, mimic, draw_square, turtle_teleop_key), turtlesim,
the web servers, and the start of a lesson
(``lesson_scripts``); docs/dev/architecture.md ("How a program stops") has the table. Its rclpy
half is ``ros_tutorials_common.ros`` (``init``, ``node_stopped``, ``run_node``, ``SpinThread``).

- ``program_main``: a console script's or a module's main. A Ctrl-C that reaches it ends the
  program with 130; the reader of its output gone (``| head``: EPIPE) ends it quietly with 0;
  output that cannot be written (a full device: ENOSPC, EIO ...) with one line and 1. A
  program that runs until stopped catches the stop itself and returns 0.
- ``StopSignals``: for a program that must finish its work before it ends (turtlesim's node and
  its PNG, a bag's summary, an action goal's cancel, a web server's tabs): SIGINT and SIGTERM
  are noted, and the program's loop asks, or is woken (``wake``).
- ``terminate_as_ctrl_c``: SIGTERM as Ctrl-C, for a wait without ROS's signal handler.
- ``is_shutdown_race``: what rclpy raises when its signal handler shut ROS down under a spin or
  a publish: the stop, not a failure.

Ctrl-C before ``program_main`` runs (while Python starts and imports rclpy) gets Python's own
KeyboardInterrupt traceback, as any ROS 2 program does (docs/dev/limits.md). From the entry on
(``count_presses``), two ways a Ctrl-C could be lost are closed:

- Python raises KeyboardInterrupt in whatever Python code runs at that instant. Raised in code
  that C calls and whose errors C drops, it is gone. So the handler counts presses, and
  ``ros_tutorials_common.wait.spin_until`` raises KeyboardInterrupt when the count changed.
- Raised inside a ``__del__`` (rclpy's Future and Task have one; the executor drops one per
  callback), Python reports it as unraisable and runs on. The unraisable hook delivers it
  again, a moment later.

The same hook says nothing of an rclpy object whose ``__init__`` a Ctrl-C cut short (its
``__del__`` fails on a missing attribute: "Exception ignored in: <function Future.__del__>").
"""

from __future__ import annotations

import _thread
import contextlib
import functools
import os
import signal
import sys
import threading
import time
from collections.abc import Callable

from ros_tutorials_common.cli import EXIT_INTERRUPTED

# A KeyboardInterrupt raised in Python code that rclpy's C++ calls while it converts a value
# (a message's __init__ inside take_message) comes out of pybind11 as this RuntimeError.
CONVERSION_FAILED = "Unable to convert call argument"

presses = 0  # Ctrl-C presses seen since count_presses()
# The presses whose KeyboardInterrupt a redelivery has raised (the hook, or wait.py's
# count): a press is delivered again once, not by both (one press must not end a command
# twice: normally, then as interrupted).
delivered = 0


def program_main(main: Callable[..., int | None]) -> Callable[..., int]:
    """A program's main, as its console script or ``python -m`` runs it: Ctrl-C's are counted
    from here on (``count_presses``); one that reaches it, or an error it caused on its way up
    (``interrupted``: argparse cut half-way fails anew in its cleanup), ends the program with
    130; output that cannot be written ends it as ``output_failed`` says."""

    @functools.wraps(main)
    def run(*args: object, **kwargs: object) -> int:
        previous = signal.getsignal(signal.SIGINT), sys.unraisablehook, sys.stdout
        try:
            count_presses()
            if not isinstance(sys.stdout, _StandardOutput):
                sys.stdout = _StandardOutput(sys.stdout)
            status = main(*args, **kwargs)
            sys.stdout.flush()  # here, where an output that failed is still caught
            return 0 if status is None else status
        except KeyboardInterrupt:
            return EXIT_INTERRUPTED
        except Exception as error:
            status = output_failed(error)
            if status is not None:
                return status
            if interrupted(error):
                return EXIT_INTERRUPTED
            raise
        finally:  # for a caller that goes on (a test): what it had, unless the tool changed it
            if signal.getsignal(signal.SIGINT) is _count_and_raise and _in_main_thread():
                signal.signal(signal.SIGINT, previous[0])
            if sys.unraisablehook is _unraisable:
                sys.unraisablehook = previous[1]
            if isinstance(sys.stdout, _StandardOutput) and sys.stdout is not previous[2]:
                sys.stdout = previous[2]

    return run


class _StandardOutput:
    """sys.stdout, with each error of a write or a flush marked as standard output's (an
    OSError alone does not say which file failed)."""

    def __init__(self, stream: object) -> None:
        self._stream = stream

    def write(self, text: str) -> int:
        try:
            return self._stream.write(text)
        except OSError as error:
            error.standard_output = True
            raise

    def flush(self) -> None:
        try:
            self._stream.flush()
        except OSError as error:
            error.standard_output = True
            raise

    def __getattr__(self, name: str) -> object:
        return getattr(self._stream, name)


def output_failed(error: BaseException) -> int | None:
    """The exit status for an error writing standard output, or None if ``error`` is another.

    The reader has gone (`ros2 topic list | head`: BrokenPipeError): 0, quietly, as ROS 1's
    tools and `ls | head`. The output cannot be written (`> /dev/full`: ENOSPC, EIO ...): one
    line on standard error, 1. Either way standard output goes to /dev/null from here on, so
    that Python's flush of it at exit does not fail again ("Exception ignored ...").
    """
    if isinstance(error, BrokenPipeError):
        _discard_stdout()
        return 0
    if not (isinstance(error, OSError) and getattr(error, "standard_output", False)):
        return None
    _discard_stdout()
    reason = error.strerror or str(error)
    print(f"error: cannot write to standard output: {reason}", file=sys.stderr, flush=True)
    return 1


def _discard_stdout() -> None:
    with contextlib.suppress(OSError, ValueError):
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())


class StopSignals:
    """SIGINT and SIGTERM (or the signals given) noted and nothing more, for a program that
    finishes its work before it ends: its loop asks ``received`` between two steps, never
    interrupted inside rclpy's code or its own cleanup (where an exception raised by a signal
    leaves a half-made object behind). ``wake`` (a guard condition's trigger) makes the loop's
    wait return at the first signal. With ``second_raises`` a second signal raises
    KeyboardInterrupt: "leave now". ``restore()`` puts the previous handlers back."""

    def __init__(
        self,
        signals: tuple[signal.Signals, ...] = (signal.SIGINT, signal.SIGTERM),
        *,
        second_raises: bool = False,
    ) -> None:
        self.received: list[int] = []
        self.wake: Callable[[], object] | None = None
        self.second_raises = second_raises
        self.previous = {number: signal.signal(number, self.note) for number in signals}

    def note(self, signum: int, _frame: object) -> None:
        if self.received and self.second_raises:
            raise KeyboardInterrupt
        self.received.append(signum)
        if len(self.received) == 1 and self.wake is not None:
            self.wake()

    @property
    def name(self) -> str:
        """The first signal's name (``SIGINT``), or "" while none came."""
        return signal.Signals(self.received[0]).name if self.received else ""

    def restore(self) -> None:
        for number, handler in self.previous.items():
            signal.signal(number, handler)


def terminate_as_ctrl_c() -> None:
    """SIGTERM raises KeyboardInterrupt, as Ctrl-C: for a wait that ROS's handler does not end
    (roscore's, a bag's play)."""
    signal.signal(signal.SIGTERM, signal.default_int_handler)


# rclpy's race on Ctrl-C/SIGTERM: its signal handler shuts ROS down in its own thread, and a
# timer's publish, or the spin's next wait, then fails on the shut-down context (RCLError
# "publisher's context is invalid", "the given context is not valid"). That is the stop.
SHUT_DOWN_CONTEXT = ("context is invalid", "context is not valid")


def is_shutdown_race(error: BaseException) -> bool:
    return isinstance(error, RuntimeError) and any(m in str(error) for m in SHUT_DOWN_CONTEXT)


# Set by ros_tutorials_common.ros once rclpy.init may install rclpy's SIGINT handler: waits, a
# bounded time, until that handler has shut ROS down, so that the program's cleanup after the
# KeyboardInterrupt finds ROS down, not going down in another thread.
before_ctrl_c: Callable[[], object] | None = None


def _count_and_raise(signum: int, frame: object) -> None:
    global presses
    presses += 1
    if before_ctrl_c is not None:
        before_ctrl_c()
    raise KeyboardInterrupt


def count_presses(deliver_lost: bool = True) -> None:
    """From now on Ctrl-C raises KeyboardInterrupt as Python's own handler does, counted, and
    (deliver_lost) one lost in a __del__ is delivered again (a tool's entry, and its graph
    node: Graph; a lesson's start only counts)."""
    if _in_main_thread():  # where signal.signal works
        signal.signal(signal.SIGINT, _count_and_raise)
    if deliver_lost:
        sys.unraisablehook = _unraisable


def counts_presses() -> bool:
    """Whether Ctrl-C is this module's (count_presses), not a handler of the program's own."""
    return signal.getsignal(signal.SIGINT) is _count_and_raise


def _in_main_thread() -> bool:
    return threading.current_thread() is threading.main_thread()


def interrupted(error: BaseException | None) -> bool:
    """Whether an error is how a Ctrl-C showed: a KeyboardInterrupt in its chain (rclpy code
    cleaning up after one raised anew), or pybind11's conversion error once Ctrl-C was pressed."""
    seen = set()
    while error is not None and id(error) not in seen:
        seen.add(id(error))
        if isinstance(error, KeyboardInterrupt):
            return True
        if presses and type(error) is RuntimeError and str(error).startswith(CONVERSION_FAILED):
            return True
        error = error.__cause__ or error.__context__
    return False


def _unraisable(unraisable) -> None:
    if isinstance(unraisable.exc_value, KeyboardInterrupt):
        # On the way out (atexit, module teardown) it is the exit already under way.
        if not sys.is_finalizing() and threading.main_thread().is_alive():
            # Raised from here (signal.raise_signal, interrupt_main) it would only end this
            # hook; a bare thread, as threading's would wait here for it to start.
            try:
                _thread.start_new_thread(_interrupt_main_soon, (presses,))
            except KeyboardInterrupt:  # one more Ctrl-C while this hook ran
                _thread.start_new_thread(_interrupt_main_soon, (presses,))
    elif not cut_short(unraisable):
        sys.__unraisablehook__(unraisable)


def _interrupt_main_soon(press: int) -> None:
    global delivered
    time.sleep(0.01)  # the hook has returned by then, and the tool's code runs
    if press == 0 or delivered < press:  # not yet delivered again by wait.py's count
        delivered = press
        _thread.interrupt_main(signal.SIGINT)


def cut_short(unraisable) -> bool:
    """An rclpy object's __del__ failing on an attribute that its __init__ sets: a Ctrl-C
    raised inside that __init__ (a Future or Task of the executor, the executor rclpy.spin
    makes). rclpy's slip, not the tool's."""
    where = unraisable.object
    return (
        isinstance(unraisable.exc_value, AttributeError)
        and getattr(where, "__module__", "").startswith("rclpy.")
        and getattr(where, "__name__", "") == "__del__"
    )
