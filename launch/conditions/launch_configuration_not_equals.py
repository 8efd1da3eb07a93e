"""launch.conditions.LaunchConfigurationNotEquals."""

from __future__ import annotations

from launch._base import LaunchContext
from launch.conditions.launch_configuration_equals import LaunchConfigurationEquals


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    def evaluate(self, context: LaunchContext) -> bool:
        return not super().evaluate(context)
