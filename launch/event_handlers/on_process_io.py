"""launch.event_handlers.OnProcessIO."""

from __future__ import annotations

from typing import Any

from launch.event_handlers.on_action_event_base import _OnEvent
from launch.launch_context import LaunchContext
from launch_foundation.declarations import When


class OnProcessIO(_OnEvent):
    takes_context = False

    def __init__(
        self,
        *,
        target_action: Any = None,
        on_stdin: Any = None,
        on_stdout: Any = None,
        on_stderr: Any = None,
        handle_once: bool = False,
    ) -> None:
        super().__init__(target_action, None, handle_once)
        self.on_stdout, self.on_stderr = on_stdout, on_stderr

    def register_at(self, context: LaunchContext, when: When) -> None:
        for event, actions in (("stdout", self.on_stdout), ("stderr", self.on_stderr)):
            if actions is not None:
                self.actions = actions
                super().register_at(context, When(event, when.target))
