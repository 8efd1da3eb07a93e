"""launch.actions.LogInfo (``<log>``)."""

from __future__ import annotations

from typing import Any

from launch._base import Action, SomeSubstitutionsType, normalize, perform
from launch.actions._common import lazy_step
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext
from launch_foundation.declarations import (
    Step,
    When,
)


@expose_action("log")
class LogInfo(Action):
    """A message on the launcher's screen, when the launch reaches it."""

    def __init__(self, *, msg: SomeSubstitutionsType, **kw: Any) -> None:
        super().__init__(**kw)
        self.msg = msg

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["msg"] = parser.parse_substitution(entity.get_attr("message"))
        entity.get_attr("level", optional=True)  # every message is said at INFO here
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        parts = normalize(self.msg, self.where)
        plain = all(isinstance(p, str) for p in parts)
        if context.locals.get("runtime") and (not plain or "once" in context.locals):
            # In an event handler: performed when the event happens, as ros2 launch does
            # (the event's values, an environment variable that is set by then).
            context.sink.add_step(lazy_step(self, context, lambda: perform(self.msg, context)))
            return
        text = perform(self.msg, context)
        context.sink.add_step(Step(context.when, "log", text, where=self.where))

    def step_when_returned(self, when: When, context: LaunchContext) -> Step:
        text = "".join(
            part if isinstance(part, str) else part.perform(context)
            for part in normalize(self.msg, self.where)
        )
        return Step(when, "log", text)
