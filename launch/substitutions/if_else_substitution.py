"""launch.substitutions.IfElseSubstitution (``$(if CONDITION IF_VALUE [ELSE_VALUE])``)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launch._base import (
    SomeSubstitutionsType,
    Substitution,
    normalize_to_list_of_substitutions,
    perform,
)
from launch.frontend.expose import expose_substitution
from launch.launch_context import LaunchContext
from launch.substitutions._args import arguments
from launch.substitutions.substitution_failure import SubstitutionFailure

# A condition here is read as a YAML boolean, as ros2 launch reads it (on, yes, ... too).
_TRUE = ("true", "1", "yes", "on", "y")
_FALSE = ("false", "0", "no", "off", "n")


@expose_substitution("if")
class IfElseSubstitution(Substitution):
    """``if_value`` when the condition performs to true, else ``else_value``."""

    def __init__(
        self,
        condition: SomeSubstitutionsType,
        if_value: SomeSubstitutionsType = "",
        else_value: SomeSubstitutionsType = "",
    ) -> None:
        super().__init__()
        if if_value == else_value == "":
            raise RuntimeError("One of if_value and else_value must be specified")
        self.condition = normalize_to_list_of_substitutions(condition)
        self.if_value = normalize_to_list_of_substitutions(if_value)
        self.else_value = normalize_to_list_of_substitutions(else_value)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        data = arguments("if", data, 2, 3)
        kwargs = {"condition": data[0], "if_value": data[1]}
        if len(data) == 3:
            kwargs["else_value"] = data[2]
        return cls, kwargs

    def describe(self) -> str:
        return f"IfElseSubstitution({self.condition}, {self.if_value}, {self.else_value})"

    def perform(self, context: LaunchContext) -> str:
        text = perform(self.condition, context)
        word = text.strip().lower()
        if word not in _TRUE + _FALSE:
            raise SubstitutionFailure(
                f"{self.where}: $(if) condition must be true or false (1/0, yes/no, on/off), "
                f"not {text!r}"
            )
        return perform(self.if_value if word in _TRUE else self.else_value, context)
