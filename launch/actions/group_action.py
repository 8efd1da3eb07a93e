"""launch.actions.GroupAction (``<group>``)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launch._base import Action, LaunchDescriptionEntity, perform
from launch.actions._common import flag
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext


@expose_action("group")
class GroupAction(Action):
    """Actions in a scope of their own (launch configurations, environment, remaps...)."""

    def __init__(
        self,
        actions: Iterable[LaunchDescriptionEntity],
        *,
        scoped: bool = True,
        forwarding: bool = True,
        launch_configurations: dict[Any, Any] | None = None,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.actions = list(actions)
        self.scoped, self.forwarding = scoped, forwarding
        self.launch_configurations = launch_configurations or {}

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        for name in ("scoped", "forwarding"):
            value = entity.get_attr(name, data_type=bool, optional=True)
            if value is not None:
                kwargs[name] = parser.parse_if_substitutions(value)
        keep = entity.get_attr("keep", data_type=list[Entity], optional=True) or []
        kwargs["launch_configurations"] = {  # a name's substitutions as a key: a tuple
            tuple(parser.parse_substitution(item.get_attr("name"))): parser.parse_substitution(
                item.get_attr("value")
            )
            for item in keep
        }
        kwargs["actions"] = [
            parser.parse_action(child) for child in entity.children if child.type_name != "keep"
        ]
        return cls, kwargs

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.actions

    def execute(self, context: LaunchContext) -> None:
        inner = context
        if flag(self.scoped, context):
            inner = context.child(forwarding=flag(self.forwarding, context))
        for name, value in self.launch_configurations.items():
            inner.launch_configurations[perform(name, context)] = perform(value, context)
        for action in self.actions:
            inner.visit(action)
