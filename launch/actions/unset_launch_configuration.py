"""launch.actions.UnsetLaunchConfiguration."""

from __future__ import annotations

from typing import Any

from launch._base import Action, SomeSubstitutionsType, perform
from launch.launch_context import LaunchContext


class UnsetLaunchConfiguration(Action):
    def __init__(self, name: SomeSubstitutionsType, **kw: Any) -> None:
        super().__init__(**kw)
        self.name = name

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations.pop(perform(self.name, context), None)
