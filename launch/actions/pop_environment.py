"""launch.actions.PopEnvironment: back to the environment the last PushEnvironment kept."""

from __future__ import annotations

from typing import Any

from launch._base import Action
from launch.launch_context import LaunchContext


class PopEnvironment(Action):
    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)

    def execute(self, context: LaunchContext) -> None:
        context._pop_environment()
