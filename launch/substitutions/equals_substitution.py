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


def _same(left: str, right: str) -> bool:
    """Equal as text, or as the numbers or booleans the text names (``1.0`` equals ``1``,
    ``True`` equals ``true``)."""
    if left == right:
        return True
    words = {"true": True, "false": False}
    if left.lower() in words and right.lower() in words:
        return words[left.lower()] == words[right.lower()]
    try:
        a, b = float(left), float(right)
    except ValueError:
        return False
    return a == b or (math.isnan(a) and math.isnan(b))


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
