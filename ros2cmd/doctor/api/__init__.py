"""What every check and report of `ros2 doctor` uses, as ros2doctor's api/ has it: a check's
Result, a Report's `key: value` lines, and the warnings as Python prints them
(`<file>: <line>: UserWarning: <message>`, the file and line of the check that warns).

One module per family of checks and reports (network.py, node.py, package.py, domain.py,
platform.py, middleware.py, topic.py); settings.py what the user set, system.py the one look
at the running system they share.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass, field


def _emit(message: str, depth: int) -> None:
    frame = sys._getframe(depth + 1)
    print(f"{frame.f_code.co_filename}: {frame.f_lineno}: UserWarning: {message}", file=sys.stderr)


def doctor_warn(message: str) -> None:
    """`<file>: <line>: UserWarning: <message>`, the file and line of the caller."""
    _emit(message, 1)


def doctor_error(message: str) -> None:
    _emit(f"ERROR: {message}", 1)


@dataclass
class Result:
    error: int = 0
    warning: int = 0


@dataclass
class Report:
    name: str
    items: list[tuple[str, object]] = field(default_factory=list)

    def add(self, key: str, value: object) -> None:
        self.items.append((key, value))


def format_print(report: Report) -> None:
    """As ros2doctor: the name after a blank line, keys padded to the longest plus 4."""
    print("\n  ", report.name)
    if not report.items:
        return
    longest = max(len(key) for key, _ in report.items)
    padding = longest + 4 if longest >= 8 else 8
    for key, value in report.items:
        print(f"{key:{padding}}: {value}")
