"""launch.substitutions.TextSubstitution (one of the model's core classes, in launch._base)."""

from launch._base import TextSubstitution

__all__ = ["TextSubstitution"]
