"""launch.action: Action, the base of every action (defined with the model's core)."""

from launch._base import Action

__all__ = ["Action"]
