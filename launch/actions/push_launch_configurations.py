"""launch.actions.PushLaunchConfigurations: keep the launch configurations, to go back to
them (PopLaunchConfigurations)."""

from __future__ import annotations

from typing import Any

from launch._base import Action
from launch.launch_context import LaunchContext


class PushLaunchConfigurations(Action):
    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)

    def execute(self, context: LaunchContext) -> None:
        context._push_launch_configurations()
