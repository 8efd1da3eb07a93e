"""launch.substitutions.Command (``$(command CMD [ON_STDERR])``)."""

from __future__ import annotations

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
from launch.substitutions._args import arguments, joined, text_of
from launch.substitutions.substitution_failure import SubstitutionFailure

ON_STDERR = ("fail", "ignore", "warn", "capture")


@expose_substitution("command")
class Command(Substitution):
    """What a command prints. ``command`` is one command line: its items (text and
    substitutions) are performed and concatenated, then split as a shell would, as ros2 launch
    does (``Command(["xacro ", path, " prefix:=", ""])``). ``on_stderr``: "fail" (its stderr
    fails it), "ignore", "warn" (a warning line), "capture" (added to the output). Bounded in
    time and output; a front-end's ``$(command)`` needs the user's --allow-code."""

    def __init__(
        self,
        command: SomeSubstitutionsType,
        *,
        on_stderr: SomeSubstitutionsType = "fail",
        frontend: bool = False,
    ) -> None:
        super().__init__()
        self.command = normalize_to_list_of_substitutions(command)
        self.on_stderr = normalize_to_list_of_substitutions(on_stderr)
        self.frontend = frontend

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        data = arguments("command", data, 1, 100)
        kwargs: dict[str, Any] = {"frontend": True}
        if len(data) >= 2 and text_of(data[-1]) in ON_STDERR:
            kwargs["on_stderr"] = data[-1]
            data = data[:-1]
        kwargs["command"] = joined(data)  # unquoted words: one command line
        return cls, kwargs

    def describe(self) -> str:
        return f"Command({' + '.join(s.describe() for s in self.command)})"

    def perform(self, context: LaunchContext) -> str:
        from launch_foundation.errors import CodeRefused
        from launch_foundation.substitutions import run_command

        text = perform(self.command, context)
        if self.frontend and not context.allow_code:
            raise CodeRefused(f"{self.where}: $(command) runs a program named in the launch file")
        on_stderr = perform(self.on_stderr, context)
        if on_stderr not in ON_STDERR:
            raise SubstitutionFailure(
                f"{self.where}: on_stderr={on_stderr!r}; use one of {', '.join(ON_STDERR)}"
            )

        def error(message: str) -> SubstitutionFailure:
            return SubstitutionFailure(f"{self.where}: {message}")

        environment = context.environment if context is not None else None
        mode = (
            "capture" if on_stderr == "capture" else ("fail" if on_stderr == "fail" else "ignore")
        )
        shown = f"$(command {text})" if self.frontend else f"Command {text!r}"
        output = run_command(text, error, shown, environment, mode)
        return output
