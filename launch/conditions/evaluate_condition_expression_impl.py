"""The one reading of a condition's text (launch.conditions.evaluate_condition_expression):
what IfCondition, UnlessCondition, the front-ends' ``if``/``unless``, the boolean
substitutions and ``$(if)`` all use."""

from __future__ import annotations

from typing import Any

from launch.conditions.invalid_condition_expression_error import InvalidConditionExpressionError

VALID_TRUE_EXPRESSIONS = ["true", "1"]
VALID_FALSE_EXPRESSIONS = ["false", "0"]


def condition_truth(text: str, where: str = "", what: str = "condition") -> bool:
    """``text`` stripped, any case: true or 1, false or 0; else one line naming ``where``."""
    word = text.strip().lower()
    if word in VALID_TRUE_EXPRESSIONS:
        return True
    if word in VALID_FALSE_EXPRESSIONS:
        return False
    raise InvalidConditionExpressionError(text, what, where)


def evaluate_condition_expression(context: Any, expression: Any, where: str = "") -> bool:
    """Perform ``expression`` (text or substitutions) and read it as a condition."""
    from launch._base import perform

    return condition_truth(perform(expression, context), where)
