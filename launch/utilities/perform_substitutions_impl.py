"""launch.utilities.perform_substitutions."""

from __future__ import annotations

from typing import Any

from launch._base import perform


def perform_substitutions(context: Any, subs: Any) -> str:
    """The text of substitutions, performed in ``context`` and joined."""
    return perform(subs, context)
