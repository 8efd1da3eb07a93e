"""launch.conditions.LaunchConfigurationNotEquals."""

from __future__ import annotations

from launch.conditions.launch_configuration_equals import LaunchConfigurationEquals
from launch.launch_context import LaunchContext


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    def evaluate(self, context: LaunchContext) -> bool:
        return not super().evaluate(context)
