"""launch.conditions.IfCondition."""

from __future__ import annotations

from launch._base import (
    Condition,
    SomeSubstitutionsType,
    normalize_to_list_of_substitutions,
    perform,
)
from launch.conditions.evaluate_condition_expression_impl import condition_truth
from launch.launch_context import LaunchContext


class IfCondition(Condition):
    """True when its expression performs to true or 1 (false or 0: false; else an error)."""

    def __init__(self, predicate_expression: SomeSubstitutionsType) -> None:
        super().__init__()
        self.predicate_expression = normalize_to_list_of_substitutions(predicate_expression)

    def evaluate(self, context: LaunchContext) -> bool:
        text = perform(self.predicate_expression, context)
        return condition_truth(text, self.where, type(self).__name__)

    def describe(self) -> str:
        return f"{type(self).__name__}({self.predicate_expression!r})"
