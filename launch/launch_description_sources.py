"""launch.launch_description_sources: where an IncludeLaunchDescription finds its file. The
launcher reads the file by its name (.py, .xml, .yaml), whichever source names it."""

from __future__ import annotations

from typing import Any

from launch._base import caller_where
from launch._missing import module_getattr

__all__ = [
    "AnyLaunchDescriptionSource", "FrontendLaunchDescriptionSource",
    "LaunchDescriptionSource", "PythonLaunchDescriptionSource",
]  # fmt: skip


class LaunchDescriptionSource:
    def __init__(self, launch_file_path: Any, *args: Any, **kwargs: Any) -> None:
        self.location = launch_file_path
        self.where = caller_where()


class PythonLaunchDescriptionSource(LaunchDescriptionSource):
    pass


class AnyLaunchDescriptionSource(LaunchDescriptionSource):
    pass


class FrontendLaunchDescriptionSource(LaunchDescriptionSource):
    pass


__getattr__ = module_getattr("launch.launch_description_sources", lambda: __all__)
