"""launch.conditions.UnlessCondition."""

from __future__ import annotations

from launch.conditions.if_condition import IfCondition
from launch.launch_context import LaunchContext


class UnlessCondition(IfCondition):
    """True when its expression performs to false or 0."""

    def evaluate(self, context: LaunchContext) -> bool:
        return not super().evaluate(context)
