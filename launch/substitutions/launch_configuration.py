"""launch.substitutions.LaunchConfiguration (``$(var NAME [DEFAULT])``)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launch._base import (
    SomeSubstitutionsType,
    Substitution,
    element_at,
    normalize_to_list_of_substitutions,
    perform,
)
from launch.frontend.expose import expose_substitution
from launch.launch_context import LaunchContext
from launch.substitutions._args import arguments
from launch.substitutions.substitution_failure import SubstitutionFailure


@expose_substitution("var")
class LaunchConfiguration(Substitution):
    """The value of a launch argument or launch configuration, else ``default``."""

    def __init__(
        self, variable_name: SomeSubstitutionsType, *, default: Any = None, frontend: bool = False
    ) -> None:
        super().__init__()
        self.variable_name = normalize_to_list_of_substitutions(variable_name)
        if default is not None and not isinstance(default, (str, Substitution)):
            try:
                default = list(default)
            except TypeError:
                default = str(default)
        self.default = None if default is None else normalize_to_list_of_substitutions(default)
        self.frontend = frontend  # $(var): a missing one is named as the front-ends name it

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        data = arguments("var", data, 1, 2)
        kwargs: dict[str, Any] = {"variable_name": data[0], "frontend": True}
        if len(data) == 2:
            kwargs["default"] = data[1]
        return cls, kwargs

    def describe(self) -> str:
        return f"LaunchConfig({' + '.join(s.describe() for s in self.variable_name)})"

    def perform(self, context: LaunchContext) -> str:
        name = perform(self.variable_name, context)
        context.state.configurations_read.add(name)
        configurations = context.launch_configurations
        if name in configurations:
            if self.frontend:  # the front-ends' scope notes where each argument is read
                return context.frontend_scope.read_arg(name, element_at(self.where))
            return configurations[name]
        if self.default is not None:
            return perform(self.default, context)
        if self.frontend:
            return context.frontend_scope.read_arg(name, element_at(self.where))
        known = ", ".join(sorted(configurations)) or "none"
        raise SubstitutionFailure(
            f"{self.where}: launch configuration {name!r} is not set (set here: {known})"
        )
