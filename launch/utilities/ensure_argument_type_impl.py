"""launch.utilities.ensure_argument_type: a TypeError naming the argument and the types."""

from __future__ import annotations

import inspect
from collections.abc import Iterable
from typing import Any


def ensure_argument_type(
    argument: Any, types: Any, argument_name: str, caller: str | None = None
) -> None:
    """Raise TypeError unless ``argument`` is an instance of one of ``types`` (a class in
    ``types`` also accepts its subclasses given as classes)."""
    if not isinstance(argument_name, str):
        raise TypeError("argument_name must be a str")
    if caller is not None and not isinstance(caller, str):
        raise TypeError("caller must be a str")
    kinds = list(types) if isinstance(types, Iterable) else [types]
    for kind in kinds:
        if not inspect.isclass(kind):
            raise TypeError(f"types must be classes, got {kind!r}")
        if isinstance(argument, kind) or (inspect.isclass(argument) and issubclass(argument, kind)):
            return
    names = ", ".join(f"'{kind.__name__}'" for kind in kinds)
    who = f"{caller}: " if caller else ""
    raise TypeError(
        f"{who}Expected '{argument_name}' to be one of [{names}], "
        f"but got '{argument}' of type '{type(argument)}'"
    )
