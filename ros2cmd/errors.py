"""The ros2 command's errors: the toolkit's ToolError (ros_tutorials_common.errors), and how
rclpy's exceptions are caught without loading rclpy."""

from __future__ import annotations

import sys

from ros_tutorials_common.errors import ToolError, ToolFailure

__all__ = ["ToolError", "ToolFailure", "rclpy_error"]


def rclpy_error(module: str, name: str) -> tuple[type[BaseException], ...]:
    """rclpy's exception class, as a tuple for `except`; () while rclpy is not loaded (nothing
    can have raised it then, and loading it to look would cost what the lazy imports save)."""
    loaded = sys.modules.get(module)
    return (getattr(loaded, name),) if loaded is not None else ()
