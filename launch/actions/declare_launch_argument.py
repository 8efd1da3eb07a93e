"""launch.actions.DeclareLaunchArgument (``<arg>``)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launch._base import Action, SomeSubstitutionsType, normalize_to_list_of_substitutions, perform
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext


@expose_action("arg")
class DeclareLaunchArgument(Action):
    """A launch argument: ``name:=value`` on the command line or from an includer, else its
    default."""

    def __init__(
        self,
        name: str,
        *,
        default_value: SomeSubstitutionsType | None = None,
        description: str | None = None,
        choices: Iterable[str] | None = None,
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        self.name = name
        self.default_value = (
            None if default_value is None else normalize_to_list_of_substitutions(default_value)
        )
        self.choices = list(choices) if choices is not None else None
        if self.choices is not None:  # as ros2 launch says them (--show-args too)
            if description is None:
                description = f"One of: {self.choices}"
            else:
                description += ("" if description.endswith(".") else ".") + (
                    f" Valid choices are: {self.choices}"
                )
        self.description = description

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["name"] = entity.get_attr("name")
        default = entity.get_attr("default", optional=True)
        if default is not None:
            kwargs["default_value"] = parser.parse_substitution(default)
        kwargs["description"] = entity.get_attr("description", optional=True)
        choices = entity.get_attr("choice", data_type=list[Entity], optional=True)
        if choices:
            kwargs["choices"] = [choice.get_attr("value") for choice in choices]
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        context.declare(self.name)
        if self.name not in context.launch_configurations:
            if self.default_value is None:
                raise self.error(f"argument {self.name!r} is required: pass {self.name}:=<value>")
            context.launch_configurations[self.name] = perform(self.default_value, context)
        value = context.launch_configurations[self.name]
        if self.choices is not None and value not in self.choices:
            raise self.error(f"argument {self.name!r} is {value!r}; choose one of {self.choices}")
