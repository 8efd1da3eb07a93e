"""Ctrl-C in the tools (ros2, the ROS 1 front-ends, rosbag, rosrun, the launcher).

A tool catches KeyboardInterrupt at its entry (``exits_130_on_ctrl_c``; ``ros2cmd.cli.execute``
decides 0 or 130 for a running command). Before that, while Python starts and imports rclpy,
a Ctrl-C prints Python's own KeyboardInterrupt traceback, as it does for any ROS 2 program
(docs/dev/limits.md). From the entry on (``count_presses``), two ways a Ctrl-C could be lost
are closed:

- Python raises KeyboardInterrupt in whatever Python code runs at that instant. Raised in code
  that C calls and whose errors C drops, it is gone. So the handler counts presses, and
  ``ros2cmd.wait.spin_until`` raises KeyboardInterrupt when the count changed.
- Raised inside a ``__del__`` (rclpy's Future and Task have one; the executor drops one per
  callback), Python reports it as unraisable and runs on. The unraisable hook delivers it
  again, a moment later.

The same hook says nothing of an rclpy object whose ``__init__`` a Ctrl-C cut short (its
``__del__`` fails on a missing attribute: "Exception ignored in: <function Future.__del__>").
"""

from __future__ import annotations

import _thread
import functools
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
# The presses whose KeyboardInterrupt a redelivery has raised (the hook, or ros2cmd.wait's
# count): a press is delivered again once, not by both (one press must not end a command
# twice: normally, then as interrupted).
delivered = 0


def exits_130_on_ctrl_c(main: Callable[..., int]) -> Callable[..., int]:
    """A console script's main: Ctrl-C's are counted from here on (``count_presses``), and one
    that reaches it, or an error it caused on its way up (``interrupted``: argparse cut
    half-way fails anew in its cleanup), ends the tool with status 130."""

    @functools.wraps(main)
    def run(*args: object, **kwargs: object) -> int:
        previous = signal.getsignal(signal.SIGINT), sys.unraisablehook
        try:
            count_presses()
            return main(*args, **kwargs)
        except KeyboardInterrupt:
            return EXIT_INTERRUPTED
        except Exception as error:
            if interrupted(error):
                return EXIT_INTERRUPTED
            raise
        finally:  # for a caller that goes on (a test): what it had, unless the tool changed it
            if signal.getsignal(signal.SIGINT) is _count_and_raise and _in_main_thread():
                signal.signal(signal.SIGINT, previous[0])
            if sys.unraisablehook is _unraisable:
                sys.unraisablehook = previous[1]

    return run


def _count_and_raise(signum: int, frame: object) -> None:
    global presses
    presses += 1
    raise KeyboardInterrupt


def count_presses() -> None:
    """From now on Ctrl-C raises KeyboardInterrupt as Python's own handler does, counted, and
    one lost in a __del__ is delivered again (a tool's entry, and its graph node: Graph)."""
    if _in_main_thread():  # where signal.signal works
        signal.signal(signal.SIGINT, _count_and_raise)
    sys.unraisablehook = _unraisable


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
    if press == 0 or delivered < press:  # not yet delivered again by ros2cmd.wait's count
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
