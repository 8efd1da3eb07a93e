"""launch.events.matchers: matchers that pick the action an event is for."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def matches_action(target_action: Any) -> Callable[[Any], bool]:
    """A matcher true for ``target_action`` itself (``lifecycle_node_matcher=`` of a lifecycle
    ChangeState event, ``process_matcher=`` of a process event)."""
    return lambda action: action is target_action
