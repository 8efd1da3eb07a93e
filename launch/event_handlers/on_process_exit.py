"""launch.event_handlers.OnProcessExit."""

from __future__ import annotations

from typing import Any

from launch.event_handlers.on_action_event_base import _OnEvent


class OnProcessExit(_OnEvent):
    event = "exit"

    def __init__(
        self, *, target_action: Any = None, on_exit: Any, handle_once: bool = False
    ) -> None:
        super().__init__(target_action, on_exit, handle_once)
