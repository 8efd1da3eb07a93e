"""launch.actions.SetLaunchConfiguration (``<let>``)."""

from __future__ import annotations

from launch._base import perform
from launch.actions._common import NameValueAction
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext


@expose_action("let")
class SetLaunchConfiguration(NameValueAction):
    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations[perform(self.name, context)] = perform(self.value, context)
