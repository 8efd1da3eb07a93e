"""launch.substitution: Substitution, the base of every substitution."""

from launch._base import Substitution

__all__ = ["Substitution"]
