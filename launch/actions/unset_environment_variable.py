"""launch.actions.UnsetEnvironmentVariable (``<unset_env>``)."""

from __future__ import annotations

from typing import Any

from launch._base import Action, SomeSubstitutionsType
from launch.actions._common import env_name
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext


@expose_action("unset_env")
class UnsetEnvironmentVariable(Action):
    def __init__(self, name: SomeSubstitutionsType, **kw: Any) -> None:
        super().__init__(**kw)
        self.name = name

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["name"] = parser.parse_substitution(entity.get_attr("name"))
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        context.set_env(env_name(self, context), None)
