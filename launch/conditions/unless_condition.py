"""launch.conditions.UnlessCondition."""

from __future__ import annotations

from launch._base import LaunchContext
from launch.conditions.if_condition import IfCondition


class UnlessCondition(IfCondition):
    """True when its expression performs to false or 0."""

    def evaluate(self, context: LaunchContext) -> bool:
        return not super().evaluate(context)
