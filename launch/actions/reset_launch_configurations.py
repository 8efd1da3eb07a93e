"""launch.actions.ResetLaunchConfigurations (``<reset>``)."""

from __future__ import annotations

from typing import Any

from launch._base import Action, perform
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext


@expose_action("reset")
class ResetLaunchConfigurations(Action):
    """Forget every launch configuration but the ones given (`<reset>` with `<keep>`s); the
    kept values are performed before anything is forgotten, as in ros2/launch."""

    def __init__(self, launch_configurations: dict | None = None, **kw: Any) -> None:
        super().__init__(**kw)
        self.launch_configurations = dict(launch_configurations or {})

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        keep = entity.get_attr("keep", data_type=list[Entity], optional=True) or []
        kwargs["launch_configurations"] = {
            tuple(parser.parse_substitution(item.get_attr("name"))): parser.parse_substitution(
                item.get_attr("value")
            )
            for item in keep
        }
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        kept = {
            perform(name, context): perform(value, context)
            for name, value in self.launch_configurations.items()
        }
        context.launch_configurations.clear()
        context.launch_configurations.update(kept)
