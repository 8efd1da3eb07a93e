"""launch.substitutions.ThisLaunchFile (``$(filename)``)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launch._base import Substitution
from launch.frontend.expose import expose_substitution
from launch.launch_context import LaunchContext
from launch.substitutions._args import arguments
from launch.substitutions.substitution_failure import SubstitutionFailure


@expose_substitution("filename")
class ThisLaunchFile(Substitution):
    """The path of the launch file being read."""

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        arguments("filename", data, 0, 0)
        return cls, {}

    def describe(self) -> str:
        return f"{type(self).__name__}()"

    def perform(self, context: LaunchContext) -> str:
        path = context.current_launch_file_path
        if path is None:
            raise SubstitutionFailure(
                f"{self.where}: {type(self).__name__} used outside a launch file"
            )
        return str(path)
