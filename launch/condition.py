"""launch.condition: Condition, the base of launch.conditions."""

from launch._base import Condition

__all__ = ["Condition"]
