"""launch.LaunchDescription: the list of actions generate_launch_description() returns."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launch._base import LaunchDescriptionEntity
from launch.actions import DeclareLaunchArgument  # also importable from here, as upstream
from launch.launch_context import LaunchContext


class LaunchDescription(LaunchDescriptionEntity):
    def __init__(
        self,
        initial_entities: Iterable[LaunchDescriptionEntity] | None = None,
        *,
        deprecated_reason: str | None = None,
    ) -> None:
        super().__init__()
        self.entities = list(initial_entities or [])
        self.deprecated_reason = deprecated_reason

    def add_action(self, action: LaunchDescriptionEntity) -> None:
        self.entities.append(action)

    def add_entity(self, entity: LaunchDescriptionEntity) -> None:
        self.entities.append(entity)

    @property
    def deprecated(self) -> bool:
        return self.deprecated_reason is not None

    def describe(self) -> str:
        return f"LaunchDescription({len(self.entities)} entities)"

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.entities

    def visit(self, context: Any) -> list[LaunchDescriptionEntity]:
        """Its entities, to visit next (the executor's LaunchContext.visit runs them)."""
        return self.entities

    def execute(self, context: LaunchContext) -> list[Any]:
        if self.deprecated_reason:
            context.sink.warn(f"{self.where}: deprecated: {self.deprecated_reason}")
        return self.entities

    def get_launch_arguments(self) -> list[Any]:
        """The DeclareLaunchArgument actions, also in groups and timers (not in includes)."""
        found, stack = [], list(reversed(self.entities))
        while stack:
            entity = stack.pop()
            if isinstance(entity, DeclareLaunchArgument):
                found.append(entity)
            elif isinstance(entity, LaunchDescriptionEntity):
                stack.extend(reversed(entity.describe_sub_entities()))
        return found
