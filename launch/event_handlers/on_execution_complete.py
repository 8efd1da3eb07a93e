"""launch.event_handlers.OnExecutionComplete."""

from __future__ import annotations

from typing import Any

from launch.event_handlers.on_action_event_base import _OnEvent


class OnExecutionComplete(_OnEvent):
    """For a process, its execution completes when it exits."""

    event = "exit"

    def __init__(
        self, *, target_action: Any = None, on_completion: Any, handle_once: bool = False
    ) -> None:
        super().__init__(target_action, on_completion, handle_once)

    def matches(self, event: Any) -> bool:
        """An ExecutionComplete of the target action (of any, without one)."""
        from launch.events import ExecutionComplete

        if not isinstance(event, ExecutionComplete):
            return False
        return self.target_action is None or event.action is self.target_action
