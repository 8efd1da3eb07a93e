"""launch.actions.TimerAction (``<timer>``)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launch._base import Action, LaunchDescriptionEntity, SomeSubstitutionsType
from launch.actions._common import flag, seconds
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext


@expose_action("timer")
class TimerAction(Action):
    """Its actions happen ``period`` seconds later."""

    def __init__(
        self,
        *,
        period: float | SomeSubstitutionsType,
        actions: Iterable[LaunchDescriptionEntity],
        cancel_on_shutdown: bool = True,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.period = period
        self.actions = list(actions)
        self.cancel_on_shutdown = cancel_on_shutdown

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        period = entity.get_attr("period", data_type=float, can_be_str=True)
        kwargs["period"] = parser.parse_if_substitutions(period)
        kwargs["actions"] = [parser.parse_action(child) for child in entity.children]
        return cls, kwargs

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.actions

    def execute(self, context: LaunchContext) -> None:
        period = seconds(self.period, context, self.where, "TimerAction period")
        if not flag(self.cancel_on_shutdown, context):
            context.sink.warn(
                f"{self.where}: TimerAction(cancel_on_shutdown=False): a shutdown cancels "
                "every timer in this launcher, this one too"
            )
        later = context.child(when=context.when.later(period))
        for action in self.actions:
            later.visit(action)
