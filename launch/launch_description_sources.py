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
    """A LaunchDescription given as it is, or where to read one (``location``: a file path,
    text or substitutions). The launcher reads the file by its name's ending."""

    def __init__(
        self,
        launch_description: Any = None,
        location: Any = "<string>",
        method: str = "interpreted python launch file",
    ) -> None:
        self.where = caller_where()
        self._launch_description = launch_description
        self.location = location
        self.method = method

    def try_get_launch_description_without_context(self) -> Any:
        return self._launch_description

    def get_launch_description(self, context: Any) -> Any:
        if self._launch_description is None:
            raise RuntimeError(
                "LaunchDescriptionSource.get_launch_description(): called without a "
                "launch description being set"
            )
        return self._launch_description


class _FileSource(LaunchDescriptionSource):
    """A source named by its file (text or substitutions)."""

    def __init__(self, launch_file_path: Any, *args: Any, **kwargs: Any) -> None:
        super().__init__(None, launch_file_path)


class PythonLaunchDescriptionSource(_FileSource):
    pass


class AnyLaunchDescriptionSource(_FileSource):
    pass


class FrontendLaunchDescriptionSource(_FileSource):
    pass


__getattr__ = module_getattr("launch.launch_description_sources", lambda: __all__)
