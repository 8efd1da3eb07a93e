"""Single key presses from the terminal for `ros2 bag record|play` (rosbag2's keyboard_handler).

SPACE pauses and resumes; the player also takes CURSOR_RIGHT (next message), CURSOR_UP and
CURSOR_DOWN (rate +/- 10%), and ROS 1's `s` (step). Without a terminal there are no keys and
waiting is sleeping.
"""

from __future__ import annotations

import contextlib
import os
import select
import sys
import termios
import time
import tty
from typing import Any

ARROWS = {"A": "CURSOR_UP", "B": "CURSOR_DOWN", "C": "CURSOR_RIGHT", "D": "CURSOR_LEFT"}


class Keyboard:
    """The terminal in cbreak mode (no echo, no line buffering) until restore()."""

    def __init__(self, enabled: bool = True) -> None:
        self.fd = -1
        self.saved: Any = None
        if not enabled:
            return
        with contextlib.suppress(AttributeError, ValueError, OSError, termios.error):
            if sys.stdin.isatty():
                fd = sys.stdin.fileno()
                self.saved = termios.tcgetattr(fd)
                tty.setcbreak(fd)
                self.fd = fd

    @property
    def active(self) -> bool:
        return self.fd >= 0

    def wait(self, timeout: float) -> str:
        """The key pressed within timeout seconds ('' if none): 'SPACE', an arrow's name, or
        the character; sleeps without a terminal."""
        if not self.active:
            if timeout > 0:
                time.sleep(timeout)
            return ""
        ready, _, _ = select.select([self.fd], [], [], max(timeout, 0.0))
        if not ready:
            return ""
        key = os.read(self.fd, 1).decode(errors="replace")
        if key == " ":
            return "SPACE"
        if key == "\x1b":  # an arrow is ESC [ A..D, sent in one go
            rest = ""
            while len(rest) < 2 and select.select([self.fd], [], [], 0.05)[0]:
                rest += os.read(self.fd, 1).decode(errors="replace")
            return ARROWS.get(rest[1:], "ESCAPE") if rest[:1] in ("[", "O") else "ESCAPE"
        return key

    def restore(self) -> None:
        if self.active:
            with contextlib.suppress(termios.error, OSError):
                termios.tcsetattr(self.fd, termios.TCSADRAIN, self.saved)
            self.fd = -1
