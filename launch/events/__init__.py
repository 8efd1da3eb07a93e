"""launch.events: the events an event handler receives, and Shutdown, which ends the launch."""

from __future__ import annotations

from typing import Any

from launch._missing import module_getattr
from launch.event import Event
from launch.events import process
from launch.events.execution_complete import ExecutionComplete
from launch.events.matchers import matches_action
from launch.events.process import (
    ProcessExited,
    ProcessIO,
    ProcessStarted,
    ProcessStderr,
    ProcessStdout,
)

__all__ = [
    "Event", "ExecutionComplete", "ProcessExited", "ProcessIO", "ProcessStarted",
    "ProcessStderr", "ProcessStdout", "Shutdown", "matches_action", "process",
]  # fmt: skip


class Shutdown(Event):
    def __init__(self, *, reason: str = "reason not given", due_to_sigint: bool = False) -> None:
        super().__init__(reason=reason, due_to_sigint=due_to_sigint)


__getattr__ = module_getattr("launch.events", lambda: __all__)


def event_from(info: dict[str, Any]) -> Event:
    """The event object a handler's function or LocalSubstitution sees, from what the
    launcher reports (``text`` as bytes, as ros2 launch gives it)."""
    fields = dict(info)
    if isinstance(fields.get("text"), str):
        fields["text"] = fields["text"].encode()
    if "reason" in fields:
        return Shutdown(reason=fields["reason"])
    kind = ProcessIO if "text" in fields else ProcessExited if "returncode" in fields else Event
    return kind(**fields)
