"""launch.conditions: whether an action runs."""

from __future__ import annotations

from launch._base import Condition, LaunchContext, SomeSubstitutionsType, perform
from launch._missing import module_getattr
from launch_foundation.substitutions import to_bool

__all__ = [
    "IfCondition", "LaunchConfigurationEquals", "LaunchConfigurationNotEquals", "UnlessCondition",
]  # fmt: skip


class IfCondition(Condition):
    def __init__(self, predicate_expression: SomeSubstitutionsType) -> None:
        super().__init__()
        self.predicate_expression = predicate_expression

    def evaluate(self, context: LaunchContext) -> bool:
        text = perform(self.predicate_expression, context)
        return to_bool(text, self.where, type(self).__name__)


class UnlessCondition(IfCondition):
    def evaluate(self, context: LaunchContext) -> bool:
        return not super().evaluate(context)


class LaunchConfigurationEquals(Condition):
    def __init__(self, launch_configuration_name: str, expected_value: object) -> None:
        super().__init__()
        self.name = launch_configuration_name
        self.expected_value = expected_value

    def evaluate(self, context: LaunchContext) -> bool:
        value = context.launch_configurations.get(self.name)
        expected = self.expected_value
        if expected is not None and not isinstance(expected, str):
            expected = perform(expected, context)
        return value == expected


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    def evaluate(self, context: LaunchContext) -> bool:
        return not super().evaluate(context)


__getattr__ = module_getattr("launch.conditions", lambda: __all__)
