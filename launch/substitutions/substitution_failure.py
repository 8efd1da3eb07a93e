"""launch.substitutions.SubstitutionFailure (defined with the model's core, launch._base)."""

from launch._base import SubstitutionFailure

__all__ = ["SubstitutionFailure"]
