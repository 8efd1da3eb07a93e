"""launch.substitutions.PathJoinSubstitution and PathSubstitution (``/`` joins paths)."""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from launch._base import Substitution, perform
from launch.launch_context import LaunchContext


class PathJoinSubstitution(Substitution):
    """Its parts performed and joined as a path (``os.path.join``); a part that is a list of
    text and substitutions is one part, its items concatenated."""

    def __init__(self, substitutions: Iterable[Any]) -> None:
        super().__init__()
        self.substitutions = list(substitutions)

    def perform(self, context: LaunchContext) -> str:
        parts = [perform(part, context) for part in self.substitutions]
        return os.path.join(*parts) if parts else ""

    def describe(self) -> str:
        return f"PathJoin({self.substitutions!r})"

    def __truediv__(self, other: Any) -> PathJoinSubstitution:
        return PathJoinSubstitution([*self.substitutions, other])


class PathSubstitution(Substitution):
    """A path (text, a ``pathlib.Path`` or substitutions); ``/`` joins another part to it:
    ``PathSubstitution(FindPackageShare("pkg")) / "urdf" / "robot.urdf"``."""

    def __init__(self, path: Any) -> None:
        super().__init__()
        self.path = str(path) if isinstance(path, Path) else path

    def perform(self, context: LaunchContext) -> str:
        return perform(self.path, context)

    def describe(self) -> str:
        return f"Path({self.path!r})"

    def __truediv__(self, other: Any) -> PathJoinSubstitution:
        return PathJoinSubstitution([self, str(other) if isinstance(other, Path) else other])
