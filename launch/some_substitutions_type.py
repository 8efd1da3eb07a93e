"""launch.some_substitutions_type: what a substitutions argument may be."""

from launch._base import SomeSubstitutionsType, Substitution

SomeSubstitutionsType_types_tuple = (str, Substitution, list, tuple)

__all__ = ["SomeSubstitutionsType", "SomeSubstitutionsType_types_tuple"]
