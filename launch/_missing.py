"""One clear line for a name of ros2/launch that this stand-in does not have."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launch._base import caller_where
from launch_foundation.errors import LaunchError


def module_getattr(module: str, names: Callable[[], list[str]]) -> Callable[[str], Any]:
    """A module ``__getattr__``: ``from launch.actions import Missing`` names what is missing."""

    def __getattr__(name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        have = ", ".join(sorted(n for n in names() if not n.startswith("_") and n[0].isupper()))
        raise LaunchError(
            f"{caller_where()}: {module}.{name} is not in this launcher's launch API "
            f"(it has: {have})"
        )

    return __getattr__
