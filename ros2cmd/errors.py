"""The one error type of the ros2 command: a message for the user, printed as one line."""

from __future__ import annotations

import sys


class ToolError(Exception):
    """Something the user asked for cannot be done; str(error) says why, in one line."""

    prefix = "error: "  # how cli.execute prints it: `error: unknown node '/x' ...`


class ToolFailure(ToolError):
    """A failure ros2cli reports in its own words (`Setting parameter failed: ...`): the line
    is printed as it is, without the 'error: ' prefix; the exit status is 1 all the same."""

    prefix = ""


def rclpy_error(module: str, name: str) -> tuple[type[BaseException], ...]:
    """rclpy's exception class, as a tuple for `except`; () while rclpy is not loaded (nothing
    can have raised it then, and loading it to look would cost what the lazy imports save)."""
    loaded = sys.modules.get(module)
    return (getattr(loaded, name),) if loaded is not None else ()
