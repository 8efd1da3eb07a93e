"""launch.substitutions.LocalSubstitution: a value of the event an event handler runs for."""

from __future__ import annotations

from launch._base import Substitution
from launch.launch_context import LaunchContext
from launch.substitutions.substitution_failure import SubstitutionFailure


class LocalSubstitution(Substitution):
    """``LocalSubstitution("event.reason")``: evaluated in the context's locals."""

    def __init__(self, expression: str, description: str | None = None) -> None:
        super().__init__()
        self.expression = expression
        self.description = description

    def describe(self) -> str:
        return self.description or f"LocalVar('{self.expression}')"

    def perform(self, context: LaunchContext) -> str:
        local_names = context.get_locals_as_dict()
        if not local_names:
            raise SubstitutionFailure(
                f"{self.where}: LocalSubstitution({self.expression!r}) outside an event handler"
            )
        try:
            return str(eval(self.expression, {}, local_names))
        except Exception as error:
            raise SubstitutionFailure(
                f"{self.where}: LocalSubstitution({self.expression!r}): {error}"
            ) from None
