"""launch.utilities.normalize_to_list_of_entities."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any


def normalize_to_list_of_entities(entities: Iterable[Any]) -> list[Any]:
    """Entities, a LaunchDescription's entities included, as one flat list."""
    flat: list[Any] = []
    for entity in entities:
        if type(entity).__name__ == "LaunchDescription":  # its entities, without importing it
            flat.extend(entity.entities)
        else:
            flat.append(entity)
    return flat
