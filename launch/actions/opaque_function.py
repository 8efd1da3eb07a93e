"""launch.actions.OpaqueFunction."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from launch._base import Action, LaunchDescriptionEntity
from launch.launch_context import LaunchContext


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

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        return self.function(context, *self.args, **self.kwargs)
