"""What the substitutions' front-end parse methods share: the count of a ``$(name ...)``'s
arguments, checked with one message."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launch.substitutions.substitution_failure import SubstitutionFailure


def arguments(name: str, data: Sequence[Any] | None, low: int, high: int) -> list[Any]:
    """``data`` (each argument a list of substitutions), refused unless low..high of them."""
    data = list(data or [])
    if not low <= len(data) <= high:
        wanted = f"{low} argument(s)" if low == high else f"{low} to {high} arguments"
        raise SubstitutionFailure(f"$({name}) takes {wanted}, got {len(data)}")
    return data


def joined(data: Sequence[Any]) -> list[Any]:
    """Arguments written unquoted (``$(command echo -n hi)``) as one, joined by spaces."""
    out: list[Any] = []
    for index, argument in enumerate(data):
        if index:
            out.append(" ")
        out.extend(argument)
    return out


def text_of(argument: Sequence[Any]) -> str | None:
    """An argument's text when it is plain text, else None."""
    if all(hasattr(part, "text") and isinstance(part.text, str) for part in argument):
        return "".join(part.text for part in argument)
    return None
