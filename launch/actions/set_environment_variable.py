"""launch.actions.SetEnvironmentVariable (``<set_env>``)."""

from __future__ import annotations

from launch._base import perform
from launch.actions._common import NameValueAction, env_name
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext


@expose_action("set_env")
class SetEnvironmentVariable(NameValueAction):
    def execute(self, context: LaunchContext) -> None:
        context.set_env(env_name(self, context), perform(self.value, context))
