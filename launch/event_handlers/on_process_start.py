"""launch.event_handlers.OnProcessStart."""

from __future__ import annotations

from typing import Any

from launch.event_handlers.on_action_event_base import _OnEvent


class OnProcessStart(_OnEvent):
    event = "start"

    def __init__(
        self, *, target_action: Any = None, on_start: Any, handle_once: bool = False
    ) -> None:
        super().__init__(target_action, on_start, handle_once)
