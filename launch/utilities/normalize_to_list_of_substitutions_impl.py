"""launch.utilities.normalize_to_list_of_substitutions."""

from launch._base import normalize_to_list_of_substitutions

__all__ = ["normalize_to_list_of_substitutions"]
