"""The tools' wait loop (ros2cmd/wait.py): a Ctrl-C ends it even when its KeyboardInterrupt
is lost on the way (Python raises it in whatever code runs; code that C calls may drop it):
ros_tutorials_common/ctrl_c.py counts the presses."""

from __future__ import annotations

import os
import signal
import sys
import time

import pytest
from rclpy.executors import SingleThreadedExecutor

from ros2cmd import wait
from ros_tutorials_common import ctrl_c


def test_a_ctrl_c_whose_keyboardinterrupt_was_swallowed_still_ends_the_wait(
    executor: SingleThreadedExecutor, monkeypatch
):
    previous = signal.getsignal(signal.SIGINT)
    monkeypatch.setattr(sys, "unraisablehook", sys.unraisablehook)  # restored afterwards
    ctrl_c.count_presses()
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
    ctrl_c.count_presses()
    try:
        with pytest.raises(KeyboardInterrupt):
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(5)
        calls = []
        assert wait.spin_until(executor, lambda: calls.append(1) or len(calls) > 3, timeout=30)
    finally:
        signal.signal(signal.SIGINT, previous)
