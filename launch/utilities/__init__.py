"""launch.utilities: the helpers OpaqueFunction code, custom substitutions and actions use,
as ros2/launch has them (one module each)."""

from launch._missing import module_getattr
from launch.utilities.class_tools_impl import is_a, is_a_subclass, isclassinstance
from launch.utilities.ensure_argument_type_impl import ensure_argument_type
from launch.utilities.normalize_to_list_of_entities_impl import normalize_to_list_of_entities
from launch.utilities.normalize_to_list_of_substitutions_impl import (
    normalize_to_list_of_substitutions,
)
from launch.utilities.perform_substitutions_impl import perform_substitutions

__all__ = [
    "ensure_argument_type", "is_a", "is_a_subclass", "isclassinstance",
    "normalize_to_list_of_entities", "normalize_to_list_of_substitutions",
    "perform_substitutions",
]  # fmt: skip

__getattr__ = module_getattr("launch.utilities", lambda: __all__)
