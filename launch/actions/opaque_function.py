"""launch.actions.OpaqueFunction."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from launch._base import Action, LaunchDescriptionEntity
from launch.launch_context import LaunchContext
from launch_foundation.declarations import Step


class OpaqueFunction(Action):
    """A function of the launch file, called with the launch context; it may return actions."""

    def __init__(
        self,
        *,
        function: Callable[..., Any],
        args: Iterable[Any] | None = None,
        kwargs: dict[str, Any] | None = None,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.function, self.args, self.kwargs = function, list(args or []), dict(kwargs or {})

    takes_context = True  # called (event, context) when its event happens: run_handler_function

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        if context.locals.get("runtime"):  # in an event handler: called when its event happens
            from launch.event_handlers import first_event, run_handler_function

            def function(_event: Any, inner: LaunchContext) -> Any:
                return self.function(inner, *self.args, **self.kwargs)

            def call(info: dict) -> list[Step]:
                if not first_event(context, info):
                    return []
                return run_handler_function(function, info, context, self, context.when)

            context.sink.add_step(Step(context.when, "call", call=call, where=self.where))
            return None
        return self.function(context, *self.args, **self.kwargs)
