"""launch_ros.substitutions: where packages are, in this environment's ament index, and the
value a SetParameter gave (Parameter, ``$(param NAME)``)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from launch._base import Substitution, perform
from launch._missing import module_getattr
from launch.frontend.expose import expose_substitution
from launch.launch_context import LaunchContext
from ros_tutorials_common import packages

__all__ = [
    "ExecutableInPackage", "FindPackage", "FindPackagePrefix", "FindPackageShare", "Parameter",
]  # fmt: skip


class _Locate(Substitution):
    locate: Callable[[str], Path] = staticmethod(packages.prefix)

    def __init__(self, package: Any) -> None:
        super().__init__()
        self.package = package

    def perform(self, context: LaunchContext) -> str:
        name = perform(self.package, context)
        try:
            return str(type(self).locate(name))
        except LookupError as error:
            raise self.error(str(error)) from None

    @classmethod
    def parse(cls, data: list[Any]) -> tuple[type, dict[str, Any]]:
        if len(data) != 1:
            raise TypeError(f"takes 1 argument (a package), got {len(data)}")
        return cls, {"package": data[0]}

    def find(self, *parts: Any) -> Any:
        from launch.substitutions import PathJoinSubstitution

        return PathJoinSubstitution([self, *parts])

    def __truediv__(self, other: Any) -> Any:
        return self.find(other)


@expose_substitution("find-pkg-prefix")
class FindPackagePrefix(_Locate):
    locate = staticmethod(packages.prefix)


@expose_substitution("find-pkg-share")
class FindPackageShare(_Locate):
    locate = staticmethod(packages.share_directory)


class FindPackage(FindPackagePrefix):
    pass


@expose_substitution("exec-in-pkg")
class ExecutableInPackage(Substitution):
    def __init__(self, executable: Any, package: Any) -> None:
        super().__init__()
        self.executable, self.package = executable, package

    @classmethod
    def parse(cls, data: list[Any]) -> tuple[type, dict[str, Any]]:
        if len(data) != 2:
            raise TypeError(f"takes 2 arguments (an executable and a package), got {len(data)}")
        return cls, {"executable": data[0], "package": data[1]}

    def perform(self, context: LaunchContext) -> str:
        package, executable = perform(self.package, context), perform(self.executable, context)
        try:
            return packages.command(package, executable)[0]
        except packages.UnknownExecutable as error:
            raise self.error(str(error)) from None


@expose_substitution("param")
class Parameter(Substitution):
    """launch_ros's Parameter (``$(param NAME [DEFAULT])``): the value a SetParameter before it
    gave NAME (the first such), as Python's str of it; ``default`` if none did, else an error."""

    def __init__(self, name: Any, *, default: Any = None) -> None:
        super().__init__()
        self.name = name
        if default is not None and not isinstance(default, (str, Substitution, list, tuple)):
            default = str(default)
        elif isinstance(default, (list, tuple)):
            default = [item if isinstance(item, (str, Substitution)) else str(item)
                       for item in default]  # fmt: skip
        self.default = default

    @classmethod
    def parse(cls, data: list[Any]) -> tuple[type, dict[str, Any]]:
        if not 1 <= len(data) <= 2:
            raise TypeError("param substitution expects 1 or 2 arguments")
        return cls, {"name": data[0], **({"default": data[1]} if len(data) == 2 else {})}

    def describe(self) -> str:
        return f"Parameter(name={self.name!r})"

    def perform(self, context: LaunchContext) -> str:
        name = perform(self.name, context)
        for given, value in context.ros_params:
            if given == name:
                return str(value)
        if self.default is None:
            raise self.error(f"parameter {name!r} not found (no SetParameter gave it before)")
        return perform(self.default, context)


__getattr__ = module_getattr("launch_ros.substitutions", lambda: __all__)
