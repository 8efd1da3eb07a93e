"""launch.event_handlers.OnShutdown."""

from __future__ import annotations

from typing import Any

from launch.event_handlers.on_action_event_base import _OnEvent


class OnShutdown(_OnEvent):
    event = "shutdown"

    def __init__(self, *, on_shutdown: Any, handle_once: bool = False) -> None:
        super().__init__(None, on_shutdown, handle_once)
