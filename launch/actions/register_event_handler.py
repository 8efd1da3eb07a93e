"""launch.actions.RegisterEventHandler."""

from __future__ import annotations

from typing import Any

from launch._base import Action, EventHandler
from launch.launch_context import LaunchContext


class RegisterEventHandler(Action):
    def __init__(self, event_handler: EventHandler, **kw: Any) -> None:
        super().__init__(**kw)
        self.event_handler = event_handler

    def execute(self, context: LaunchContext) -> None:
        register = getattr(self.event_handler, "register", None)
        if register is None:
            raise self.error(f"{type(self.event_handler).__name__} is not an event handler")
        register(context)
