"""launch.substitutions.FindExecutable (``$(find-exec NAME)``)."""

from __future__ import annotations

import os
import shutil
import sys
from collections.abc import Sequence
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


@expose_substitution("find-exec")
class FindExecutable(Substitution):
    """The full path of an executable on the launch's PATH (and beside this Python)."""

    def __init__(self, *, name: SomeSubstitutionsType) -> None:
        super().__init__()
        self.name = normalize_to_list_of_substitutions(name)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        return cls, {"name": arguments("find-exec", data, 1, 1)[0]}

    def describe(self) -> str:
        return f"FindExec({' + '.join(s.describe() for s in self.name)})"

    def perform(self, context: LaunchContext) -> str:
        name = perform(self.name, context)
        path = (context.environment if context is not None else os.environ).get("PATH")
        found = shutil.which(name, path=path) or shutil.which(
            name, path=os.path.dirname(sys.executable)
        )
        if found is None:
            raise SubstitutionFailure(f"{self.where}: executable {name!r} not found on the PATH")
        return found
