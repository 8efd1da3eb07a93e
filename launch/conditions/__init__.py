"""launch.conditions: whether an action runs. One reading of a condition's text,
``evaluate_condition_expression``, for the Python API and the front-ends' ``if``/``unless``."""

from launch._missing import module_getattr
from launch.conditions.evaluate_condition_expression_impl import (
    condition_truth,
    evaluate_condition_expression,
)
from launch.conditions.if_condition import IfCondition
from launch.conditions.invalid_condition_expression_error import InvalidConditionExpressionError
from launch.conditions.launch_configuration_equals import LaunchConfigurationEquals
from launch.conditions.launch_configuration_not_equals import LaunchConfigurationNotEquals
from launch.conditions.unless_condition import UnlessCondition

__all__ = [
    "IfCondition", "InvalidConditionExpressionError", "LaunchConfigurationEquals",
    "LaunchConfigurationNotEquals", "UnlessCondition", "condition_truth",
    "evaluate_condition_expression",
]  # fmt: skip

__getattr__ = module_getattr("launch.conditions", lambda: __all__)
