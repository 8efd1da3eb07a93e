"""launch.events.ExecutionComplete: an action has finished executing."""

from __future__ import annotations

from typing import Any

from launch.event import Event


class ExecutionComplete(Event):
    name = "launch.events.ExecutionComplete"

    def __init__(self, *, action: Any) -> None:
        super().__init__(action=action)
