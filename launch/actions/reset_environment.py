"""launch.actions.ResetEnvironment: back to the launcher's own environment."""

from __future__ import annotations

from typing import Any

from launch._base import Action
from launch.launch_context import LaunchContext


class ResetEnvironment(Action):
    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)

    def execute(self, context: LaunchContext) -> None:
        context._reset_environment()
