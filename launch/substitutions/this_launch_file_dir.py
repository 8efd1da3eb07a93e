"""launch.substitutions.ThisLaunchFileDir (``$(dirname)``)."""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import Any

from launch.frontend.expose import expose_substitution
from launch.launch_context import LaunchContext
from launch.substitutions._args import arguments
from launch.substitutions.this_launch_file import ThisLaunchFile


@expose_substitution("dirname")
class ThisLaunchFileDir(ThisLaunchFile):
    """The folder of the launch file being read."""

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        arguments("dirname", data, 0, 0)
        return cls, {}

    def perform(self, context: LaunchContext) -> str:
        given = context.get_locals_as_dict().get("current_launch_file_directory")
        if given is not None:  # set by who loads a file
            return str(given)
        return os.path.dirname(super().perform(context))
