"""launch.substitutions.FileContent (``$(file-content PATH)``)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from launch._base import (
    SomeSubstitutionsType,
    Substitution,
    normalize_to_list_of_substitutions,
    perform,
)
from launch.frontend.expose import expose_substitution
from launch.launch_context import LaunchContext
from launch.substitutions._args import arguments
from launch.substitutions.substitution_failure import SubstitutionFailure
from ros_tutorials_common.bounded import InputError, read_text


@expose_substitution("file-content")
class FileContent(Substitution):
    """The text of a file (a relative path from the current folder, as ros2 launch opens
    it), at most 1 MiB."""

    def __init__(self, path: SomeSubstitutionsType) -> None:
        super().__init__()
        self.path = normalize_to_list_of_substitutions(path)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        return cls, {"path": arguments("file-content", data, 1, 1)[0]}

    def describe(self) -> str:
        return f"FileContent({' + '.join(s.describe() for s in self.path)})"

    def perform(self, context: LaunchContext) -> str:
        path = Path(perform(self.path, context))
        if not path.is_file():
            raise SubstitutionFailure(f"{self.where}: $(file-content): File not found: {path}")
        try:
            return read_text(path)
        except InputError as error:
            raise SubstitutionFailure(f"{self.where}: $(file-content): {error}") from None
