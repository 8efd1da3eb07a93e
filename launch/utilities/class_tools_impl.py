"""launch.utilities' class tools: is a thing a class, an instance of one, a subclass."""

from __future__ import annotations

import inspect
from typing import Any


def isclassinstance(obj: Any) -> bool:
    """Whether ``obj`` is an instance of a class (not a class itself)."""
    return hasattr(obj, "__class__") and not inspect.isclass(obj)


def is_a(obj: Any, entity_type: Any) -> bool:
    """``isinstance`` for an instance (a class is no instance)."""
    return isclassinstance(obj) and isinstance(obj, entity_type)


def is_a_subclass(obj: Any, entity_type: Any) -> bool:
    """An instance of ``entity_type`` or a subclass of it."""
    if isclassinstance(obj):
        return isinstance(obj, entity_type)
    return inspect.isclass(obj) and issubclass(obj, entity_type)
