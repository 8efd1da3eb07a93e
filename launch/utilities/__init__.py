"""launch.utilities: the helpers OpaqueFunction code and custom substitutions use, as
ros2/launch has them."""

from __future__ import annotations

from typing import Any

from launch._base import LaunchContext, Substitution, normalize, perform
from launch._missing import module_getattr

__all__ = ["normalize_to_list_of_substitutions", "perform_substitutions"]


def normalize_to_list_of_substitutions(subs: Any) -> list[Substitution]:
    """Text, a substitution, or a list of them, as a list of substitutions (text becomes a
    TextSubstitution)."""
    from launch.substitutions import TextSubstitution

    return [TextSubstitution(text=item) if isinstance(item, str) else item
            for item in normalize(subs)]  # fmt: skip


def perform_substitutions(context: LaunchContext, subs: list[Substitution]) -> str:
    """The text of substitutions, performed in ``context`` and joined."""
    return perform(subs, context)


__getattr__ = module_getattr("launch.utilities", lambda: __all__)
