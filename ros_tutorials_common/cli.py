"""Command-line plumbing shared by the tutorial clients and the tools: argument types that
refuse bad values with a clear usage error, the exit status of an interrupted command (how a
program ends: shutdown.py), and help laid out as ROS 2 Jazzy's tools print it on any Python.

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


class JazzyHelpFormatter(argparse.HelpFormatter):
    """Help laid out by Python 3.12's argparse, ROS 2 Jazzy's (Ubuntu 24.04), on every Python.

    Python 3.13's argparse measures a sub-command at its own deeper indent (the help column of
    `ros2 -h` moves right and `interface` no longer has a line of its own) and names an option's
    value once (`-s, --storage {mcap}`). Here, as on 3.12, a sub-command is measured at its
    parent's indent and every spelling of an option names its value (`-s {mcap}, --storage
    {mcap}`). On 3.10 to 3.12 this is argparse's own layout.
    """

    def add_argument(self, action: argparse.Action) -> None:
        widest = self._action_max_length
        super().add_argument(action)
        if action.help is not argparse.SUPPRESS:
            shown = [action, *getattr(action, "_get_subactions", list)()]
            longest = max(len(self._format_action_invocation(each)) for each in shown)
            self._action_max_length = max(widest, longest + self._current_indent)

    def _format_action_invocation(self, action: argparse.Action) -> str:
        if not action.option_strings or action.nargs == 0:
            return super()._format_action_invocation(action)
        value = self._format_args(action, self._get_default_metavar_for_optional(action))
        return ", ".join(f"{option} {value}" for option in action.option_strings)


class JazzyRawDescriptionHelpFormatter(JazzyHelpFormatter, argparse.RawDescriptionHelpFormatter):
    """JazzyHelpFormatter, with the description printed as written (`ros2 topic -h`)."""


class JazzyArgumentParser(argparse.ArgumentParser):
    """A parser whose help is JazzyHelpFormatter's unless told otherwise; its sub-parsers
    (add_subparsers makes them of the parser's own class) are too."""

    def __init__(self, *args, formatter_class=JazzyHelpFormatter, **kwargs) -> None:
        super().__init__(*args, formatter_class=formatter_class, **kwargs)


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
