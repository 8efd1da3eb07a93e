"""launch.conditions.LaunchConfigurationEquals."""

from __future__ import annotations

from typing import Any

from launch._base import Condition, perform
from launch.launch_context import LaunchContext


class LaunchConfigurationEquals(Condition):
    """True when the launch configuration's value is ``expected_value`` (performed); with
    ``expected_value`` None, when the configuration is not set."""

    def __init__(self, launch_configuration_name: str, expected_value: Any) -> None:
        import warnings

        warnings.warn(
            f"{type(self).__name__} is deprecated in ros2 launch; use IfCondition with "
            "EqualsSubstitution (or NotEqualsSubstitution)",
            UserWarning,
            stacklevel=2,
        )
        super().__init__()
        self.launch_configuration_name = launch_configuration_name
        self.expected_value = expected_value

    def evaluate(self, context: LaunchContext) -> bool:
        value = context.launch_configurations.get(self.launch_configuration_name)
        expected = self.expected_value
        if expected is not None:
            expected = perform(expected, context)
        return value == expected

    def describe(self) -> str:
        return f"{type(self).__name__}({self.launch_configuration_name!r})"
