"""launch.actions.PopLaunchConfigurations: back to the configurations the last
PushLaunchConfigurations kept."""

from __future__ import annotations

from typing import Any

from launch._base import Action
from launch.launch_context import LaunchContext


class PopLaunchConfigurations(Action):
    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)

    def execute(self, context: LaunchContext) -> None:
        context._pop_launch_configurations()
