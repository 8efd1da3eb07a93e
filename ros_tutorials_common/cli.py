"""Command-line plumbing shared by the tutorial clients and the tools: argument types that
refuse bad values with a clear usage error, and the exit status of an interrupted command
(how a program ends: shutdown.py).

    parser.add_argument("order", type=signed_int(32))
    parser.add_argument("--timeout", type=positive_seconds, default=5.0)
"""

from __future__ import annotations

import argparse
import math
import re
from collections.abc import Callable

EXIT_INTERRUPTED = 130  # what shells report for a command ended by Ctrl-C (128 + SIGINT)
# The longest wait a command accepts: rcl counts timeouts in int64 nanoseconds (292 years),
# Python's thread waits in less; a million seconds (11.6 days) is far below both.
MAX_SECONDS = 1e6
# What the book's C++ clients read with atoll: ASCII digits with an optional sign. Python's int()
# would also take "1_000", " 5 " and Arabic-Indic digits; the clients refuse those.
_INTEGER = re.compile(r"[+-]?[0-9]+")


def signed_int(bits: int) -> Callable[[str], int]:
    """An argparse type for an integer that fits a ROS ``int<bits>`` field."""
    low, high = -(2 ** (bits - 1)), 2 ** (bits - 1) - 1

    def parse(text: str) -> int:
        if not _INTEGER.fullmatch(text):
            raise argparse.ArgumentTypeError(f"{text!r} is not an integer")
        value = int(text)
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(
                f"{text} does not fit in a {bits}-bit integer ({low} .. {high})"
            )
        return value

    parse.__name__ = f"int{bits}"  # argparse names the type in its messages
    return parse


def positive_seconds(text: str) -> float:
    """An argparse type for a duration: a number of seconds above 0, at most MAX_SECONDS."""
    value = _positive_number(text, "a positive number of seconds")
    if value > MAX_SECONDS:
        raise argparse.ArgumentTypeError(
            f"{text!r} is not a positive number of seconds up to {MAX_SECONDS:.0f}"
        )
    return value


def positive_rate(text: str) -> float:
    """An argparse type for a rate: a finite number of hertz above 0."""
    return _positive_number(text, "a positive rate in Hz")


def positive_int(text: str) -> int:
    """An argparse type for a count: an integer of at least 1."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number of at least 1")
    return value


def _positive_number(text: str, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    # nan and inf would make every deadline computed from them unreachable.
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"{text!r} is not {what}")
    return value
