"""launch.launch_description_sources: where an IncludeLaunchDescription finds its file. The
launcher reads the file by its name (.py, .xml, .yaml), whichever source names it."""

from __future__ import annotations

import importlib.util
import os
import types
from typing import Any

from launch._base import caller_where
from launch._missing import module_getattr
from launch_foundation.errors import LaunchError

__all__ = [
    "AnyLaunchDescriptionSource", "FrontendLaunchDescriptionSource",
    "InvalidPythonLaunchFileError", "LaunchDescriptionSource", "PythonLaunchDescriptionSource",
    "get_launch_description_from_python_launch_file", "load_python_launch_file_as_module",
]  # fmt: skip


class InvalidPythonLaunchFileError(LaunchError):
    """A Python file that is no launch file (no generate_launch_description())."""


def load_python_launch_file_as_module(python_launch_file_path: Any) -> types.ModuleType:
    """Run a Python file as a module of its own (FileNotFoundError if there is none)."""
    path = str(python_launch_file_path)
    if not os.path.isfile(path):
        raise FileNotFoundError(f"launch file not found: {path}")
    name = "python_launch_file_" + "".join(c if c.isalnum() else "_" for c in path)
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise InvalidPythonLaunchFileError(f"{path}: not a Python file")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def get_launch_description_from_python_launch_file(python_launch_file_path: Any) -> Any:
    """The LaunchDescription a Python launch file's generate_launch_description() returns."""
    module = load_python_launch_file_as_module(python_launch_file_path)
    generate = getattr(module, "generate_launch_description", None)
    if not callable(generate):
        raise InvalidPythonLaunchFileError(
            f"{python_launch_file_path}: a Python launch file defines generate_launch_description()"
        )
    return generate()


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
