"""launch.actions.IncludeLaunchDescription (``<include>``)."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any

from launch._base import Action, perform
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext


@expose_action("include")
class IncludeLaunchDescription(Action):
    """Another launch file, of any of the three formats, with arguments."""

    def __init__(
        self,
        launch_description_source: Any,
        *,
        launch_arguments: Iterable[tuple[Any, Any]] | None = None,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.launch_description_source = launch_description_source
        self.launch_arguments = list(launch_arguments or [])
        # Where a front-end wrote each argument (<arg> lines): the launcher then checks them
        # against the included file's declarations and names those lines in its warnings.
        self.arguments_at: dict[str, str] | None = None

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        from launch.launch_description_sources import AnyLaunchDescriptionSource

        _, kwargs = super().parse(entity, parser)
        source = parser.parse_substitution(entity.get_attr("file"))
        kwargs["launch_description_source"] = AnyLaunchDescriptionSource(source)
        arguments = entity.get_attr("arg", data_type=list[Entity], optional=True) or []
        kwargs["launch_arguments"] = [
            (item.get_attr("name"), parser.parse_substitution(item.get_attr("value")))
            + ((condition,) if (condition := parser.parse_condition(item)) else ())
            for item in arguments
        ]
        return cls, kwargs

    def execute(self, context: LaunchContext) -> list[Any] | None:
        source = self.launch_description_source
        given_description = getattr(source, "try_get_launch_description_without_context", None)
        description = given_description() if given_description is not None else source
        if type(description).__name__ != "LaunchDescription":  # a file to read
            description = None
        if description is not None:  # a description given as it is: its arguments set, then it
            for name, value, *condition in self.launch_arguments:
                if not condition or condition[0].evaluate(context):
                    context.launch_configurations[perform(name, context)] = perform(value, context)
            return [description]
        location = getattr(source, "location", source)
        path = Path(perform(location, context))
        if not path.is_absolute():
            path = context.launch_file.parent / path
        if not path.is_file():
            raise self.error(f"included launch file {path} does not exist")
        # Every given argument becomes a launch configuration of the included file, declared
        # there or not; the included file sees the includer's configurations too, and what it
        # sets stays set after it (ros2 launch does not scope includes; the sink does this).
        given = {}
        for name, value, *condition in self.launch_arguments:
            # a front-end's <arg if=...> inside <include> is a third item: given only if it holds
            if not condition or condition[0].evaluate(context):
                given[perform(name, context)] = perform(value, context)
        try:
            context.include(path, given, self.where, self.arguments_at)
        except RecursionError:
            raise self.error("launch files include each other too deeply") from None
        return None

    def describe(self) -> str:
        return f"IncludeLaunchDescription({self.launch_description_source!r})"

    def get_sub_entities(self) -> list[Any]:
        return []
