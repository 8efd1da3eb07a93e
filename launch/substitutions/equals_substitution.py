"""launch.substitutions.EqualsSubstitution (``$(equals LEFT RIGHT)``)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from launch._base import Substitution, normalize_to_list_of_substitutions, perform
from launch.frontend.expose import expose_substitution
from launch.launch_context import LaunchContext
from launch.substitutions._args import arguments


def _text(value: Any) -> Any:
    """A Python value compared as ros2 launch compares it: booleans as true/false, numbers
    and None as their text; text and substitutions as they perform."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, (int, float)):
        return str(value)
    return value


def _typed(text: str) -> Any:
    """Text as ros2 launch compares it: true/false (any case) a boolean, a number a float,
    anything else the text."""
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    try:
        return float(text)
    except ValueError:
        return text


def _same(left: str, right: str) -> bool:
    """Equal as booleans and numbers (1 is true, 10 is 10.0 within float precision, nan
    equals nothing), else as text."""
    a, b = _typed(left), _typed(right)
    if isinstance(a, (bool, float)) and isinstance(b, (bool, float)):
        return math.isclose(float(a), float(b))
    return a == b


@expose_substitution("equals")
class EqualsSubstitution(Substitution):
    """ "true" when its two sides are equal, else "false"."""

    def __init__(self, left: Any, right: Any) -> None:
        super().__init__()
        self.left = normalize_to_list_of_substitutions(_text(left))
        self.right = normalize_to_list_of_substitutions(_text(right))

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        left, right = arguments("equals", data, 2, 2)
        return cls, {"left": left, "right": right}

    def describe(self) -> str:
        return f"{type(self).__name__}({self.left} {self.right})"

    def perform(self, context: LaunchContext) -> str:
        return str(_same(perform(self.left, context), perform(self.right, context))).lower()
