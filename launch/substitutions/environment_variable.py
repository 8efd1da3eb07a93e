"""launch.substitutions.EnvironmentVariable (``$(env NAME [DEFAULT])``)."""

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


@expose_substitution("env")
class EnvironmentVariable(Substitution):
    """A variable of the launch's environment (``context.environment``: what
    SetEnvironmentVariable and ``<set_env>`` set before it), else ``default_value``."""

    def __init__(
        self, name: SomeSubstitutionsType, *, default_value: SomeSubstitutionsType | None = None
    ) -> None:
        super().__init__()
        self.name = normalize_to_list_of_substitutions(name)
        self.default_value = (
            None if default_value is None else normalize_to_list_of_substitutions(default_value)
        )

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        data = arguments("env", data, 1, 2)
        kwargs: dict[str, Any] = {"name": data[0]}
        if len(data) == 2:
            kwargs["default_value"] = data[1]
        return cls, kwargs

    def describe(self) -> str:
        return f"EnvVar({' + '.join(s.describe() for s in self.name)})"

    def perform(self, context: LaunchContext) -> str:
        name = perform(self.name, context)
        value = context.environment.get(name)
        if value is not None:
            return value
        if self.default_value is None:
            raise SubstitutionFailure(f"{self.where}: environment variable '{name}' does not exist")
        return perform(self.default_value, context)
