"""launch.actions.Shutdown."""

from __future__ import annotations

from typing import Any

from launch.actions.emit_event import EmitEvent
from launch.events import Shutdown as ShutdownEvent


class Shutdown(EmitEvent):
    """launch.actions.Shutdown: EmitEvent(event=Shutdown(reason=...))."""

    def __init__(self, *, reason: str = "reason not given", **kw: Any) -> None:
        super().__init__(event=ShutdownEvent(reason=reason), **kw)
