"""launch.actions.SetLaunchConfiguration (``<let>``)."""

from __future__ import annotations

from launch._base import (
    LaunchContext,
    perform,
)
from launch.actions._common import NameValueAction
from launch.frontend.expose import expose_action


@expose_action("let")
class SetLaunchConfiguration(NameValueAction):
    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations[perform(self.name, context)] = perform(self.value, context)
