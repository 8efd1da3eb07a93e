"""launch.actions.EmitEvent."""

from __future__ import annotations

from typing import Any

from launch._base import Action, perform
from launch.actions._common import lazy_step
from launch.events import Shutdown as ShutdownEvent
from launch.launch_context import LaunchContext
from launch_foundation.declarations import (
    Step,
    When,
)


class EmitEvent(Action):
    """Only the Shutdown event is emitted by launch files here."""

    def __init__(self, *, event: Any, **kw: Any) -> None:
        super().__init__(**kw)
        self.event = event

    def execute(self, context: LaunchContext) -> None:
        if not isinstance(self.event, ShutdownEvent):
            raise self.error(
                f"EmitEvent({type(self.event).__name__}) is not supported here; only "
                "EmitEvent(event=Shutdown(...))"
            )
        plain = isinstance(self.event.reason, str)
        if context.locals.get("runtime") and (not plain or "once" in context.locals):
            reason = lambda: perform(self.event.reason, context)  # noqa: E731
            context.sink.add_step(lazy_step(self, context, reason, "shutdown"))
            return
        reason = perform(self.event.reason, context)
        context.sink.add_step(Step(context.when, "shutdown", reason, where=self.where))

    def step_when_returned(self, when: When, context: LaunchContext) -> Step:
        return Step(when, "shutdown", str(getattr(self.event, "reason", "")))
