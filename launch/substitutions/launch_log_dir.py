"""launch.substitutions.LaunchLogDir (``$(launch_log_dir)``, ``$(log_dir)``)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launch._base import Substitution
from launch.frontend.expose import expose_substitution
from launch.launch_context import LaunchContext
from launch.substitutions._args import arguments


class LaunchLogDir(Substitution):
    """The folder of this launch's log files (launch.logging.launch_config.log_dir)."""

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        arguments("launch_log_dir", data, 0, 0)
        return cls, {}

    def describe(self) -> str:
        return "LaunchLogDir()"

    def perform(self, context: LaunchContext) -> str:
        from launch.logging import launch_config

        return launch_config.log_dir


expose_substitution("launch_log_dir")(LaunchLogDir)
expose_substitution("log_dir")(LaunchLogDir)
