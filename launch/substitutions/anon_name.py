"""launch.substitutions.AnonName (``$(anon NAME)``)."""

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


@expose_substitution("anon")
class AnonName(Substitution):
    """A name made unique for this launch; the same name gives the same result again."""

    def __init__(self, name: SomeSubstitutionsType) -> None:
        super().__init__()
        self.name = normalize_to_list_of_substitutions(name)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        return cls, {"name": arguments("anon", data, 1, 1)[0]}

    def describe(self) -> str:
        return f"AnonName({' + '.join(s.describe() for s in self.name)})"

    def perform(self, context: LaunchContext) -> str:
        return context.anon(perform(self.name, context))
