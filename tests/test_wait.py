"""The tools' wait loop (ros_tutorials_common/wait.py): a Ctrl-C ends it even when its
KeyboardInterrupt is lost on the way (Python raises it in whatever code runs; code that C calls
may drop it): ros_tutorials_common/shutdown.py counts the presses."""

from __future__ import annotations

import os
import signal
import sys
import time

import pytest
from rclpy.executors import SingleThreadedExecutor

from ros_tutorials_common import shutdown, wait


def test_a_ctrl_c_whose_keyboardinterrupt_was_swallowed_still_ends_the_wait(
    executor: SingleThreadedExecutor, monkeypatch
):
    previous = signal.getsignal(signal.SIGINT)
    monkeypatch.setattr(sys, "unraisablehook", sys.unraisablehook)  # restored afterwards
    shutdown.count_presses()
    swallowed = []

    def condition() -> bool:
        # Stands for C code that calls Python and drops its error: the KeyboardInterrupt is
        # raised here and never reaches spin_until.
        if not swallowed:
            try:
                os.kill(os.getpid(), signal.SIGINT)
                time.sleep(5)  # the handler raises within this sleep
            except KeyboardInterrupt:
                swallowed.append(True)
        return False

    try:
        with pytest.raises(KeyboardInterrupt):
            wait.spin_until(executor, condition, timeout=30, period=0.01)
    finally:
        signal.signal(signal.SIGINT, previous)
    assert swallowed, "the Ctrl-C never reached the condition"


def test_a_ctrl_c_before_the_wait_does_not_end_it(executor: SingleThreadedExecutor, monkeypatch):
    """Presses counted before spin_until started (and handled then) are not its business."""
    previous = signal.getsignal(signal.SIGINT)
    monkeypatch.setattr(sys, "unraisablehook", sys.unraisablehook)
    shutdown.count_presses()
    try:
        with pytest.raises(KeyboardInterrupt):
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(5)
        calls = []
        assert wait.spin_until(executor, lambda: calls.append(1) or len(calls) > 3, timeout=30)
    finally:
        signal.signal(signal.SIGINT, previous)


class _Unraisable:
    """What Python hands sys.unraisablehook for a KeyboardInterrupt raised in a __del__."""

    def __init__(self) -> None:
        self.exc_type, self.exc_value = KeyboardInterrupt, KeyboardInterrupt()
        self.exc_traceback, self.err_msg, self.object = None, None, None


def test_a_lost_ctrl_c_is_delivered_again_once_not_twice(monkeypatch):
    """A press lost in a __del__ that the wait loop has already delivered (its count) is not
    delivered a second time by the hook: a running echo once ended 0, then 130."""
    previous = signal.getsignal(signal.SIGINT)
    monkeypatch.setattr(sys, "unraisablehook", sys.unraisablehook)
    shutdown.count_presses()
    try:
        monkeypatch.setattr(shutdown, "presses", shutdown.presses + 1)  # the press, counted
        monkeypatch.setattr(shutdown, "delivered", shutdown.presses)  # and delivered by the wait
        shutdown._unraisable(_Unraisable())
        time.sleep(0.5)  # the hook's redelivery would come 0.01 s later: nothing may come
        monkeypatch.setattr(shutdown, "presses", shutdown.presses + 1)  # a press nobody delivered
        shutdown._unraisable(_Unraisable())
        with pytest.raises(KeyboardInterrupt):
            time.sleep(5)  # the hook delivers this one again
    finally:
        signal.signal(signal.SIGINT, previous)
