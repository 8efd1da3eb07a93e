"""launch.substitutions.NotEqualsSubstitution (``$(not-equals LEFT RIGHT)``)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launch.frontend.expose import expose_substitution
from launch.launch_context import LaunchContext
from launch.substitutions._args import arguments
from launch.substitutions.equals_substitution import EqualsSubstitution


@expose_substitution("not-equals")
class NotEqualsSubstitution(EqualsSubstitution):
    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        left, right = arguments("not-equals", data, 2, 2)
        return cls, {"left": left, "right": right}

    def perform(self, context: LaunchContext) -> str:
        return "false" if super().perform(context) == "true" else "true"
