"""launch.conditions.InvalidConditionExpressionError."""

from __future__ import annotations

from typing import Any

from launch._base import SubstitutionFailure


class InvalidConditionExpressionError(SubstitutionFailure):
    """A condition's text that is none of true, false, 1, 0 (any case)."""

    def __init__(self, expression: str, what: str = "condition", where: str = "") -> None:
        self.expression = expression
        text = f"{what} must be true, false, 1 or 0, not {expression!r}"
        super().__init__(f"{where}: {text}" if where else text)

    @classmethod
    def at(cls, expression: str, where: Any, what: str) -> InvalidConditionExpressionError:
        return cls(expression, what, where)
