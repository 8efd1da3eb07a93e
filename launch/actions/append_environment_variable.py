"""launch.actions.AppendEnvironmentVariable (``<append_env>``)."""

from __future__ import annotations

import os
from typing import Any

from launch._base import Action, SomeSubstitutionsType, normalize_to_list_of_substitutions, perform
from launch.actions._common import env_name, flag
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext


@expose_action("append_env")
class AppendEnvironmentVariable(Action):
    def __init__(
        self,
        name: SomeSubstitutionsType,
        value: SomeSubstitutionsType,
        prepend: bool | SomeSubstitutionsType = False,
        separator: SomeSubstitutionsType = os.pathsep,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)
        self.separator = normalize_to_list_of_substitutions(separator)
        self.prepend = prepend

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["name"] = parser.parse_substitution(entity.get_attr("name"))
        kwargs["value"] = parser.parse_substitution(entity.get_attr("value"))
        prepend = entity.get_attr("prepend", optional=True)
        if prepend is not None:  # launch_xml's own test writes "yes"
            word = prepend.strip().lower()
            words = {"true": True, "1": True, "yes": True, "false": False, "0": False, "no": False}
            kwargs["prepend"] = words[word] if word in words else parser.parse_substitution(prepend)
        separator = entity.get_attr("separator", optional=True)
        if separator is not None:
            kwargs["separator"] = parser.parse_substitution(separator)
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        name, value = env_name(self, context), perform(self.value, context)
        old = context.environment.get(name, "")
        separator = perform(self.separator, context)
        if old:
            value = (
                value + separator + old if flag(self.prepend, context) else old + separator + value
            )
        context.set_env(name, value)
