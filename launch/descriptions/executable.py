"""launch.descriptions.Executable: a process described before it runs: its command line,
name, working folder and environment, each text or substitutions, performed by ``prepare``
into ``final_cmd``, ``final_name``, ``final_cwd``, ``final_env``."""

from __future__ import annotations

import os
from typing import Any

from launch._base import Substitution, normalize_to_list_of_substitutions, perform


class Executable:
    """What ExecuteProcess runs, as ros2/launch describes it."""

    def __init__(
        self,
        *,
        cmd: Any,
        prefix: Any = None,
        name: Any = None,
        cwd: Any = None,
        env: dict[Any, Any] | None = None,
        additional_env: dict[Any, Any] | None = None,
        arguments: Any = None,
    ) -> None:
        words = [cmd] if isinstance(cmd, (str, Substitution)) else list(cmd)
        self.cmd = [normalize_to_list_of_substitutions(word) for word in words]
        self.prefix = None if prefix is None else normalize_to_list_of_substitutions(prefix)
        self.name = None if name is None else normalize_to_list_of_substitutions(name)
        self.cwd = None if cwd is None else normalize_to_list_of_substitutions(cwd)
        self.env = env
        self.additional_env = additional_env
        self.arguments = [normalize_to_list_of_substitutions(a) for a in arguments or []]
        self.final_cmd: list[str] | None = None
        self.final_name: str | None = None
        self.final_cwd: str | None = None
        self.final_env: dict[str, str] | None = None

    def prepare(self, context: Any, action: Any) -> None:
        """Perform every part in ``context``: the command line (prefix words first, then the
        command, then the arguments), the name (the command's file name if none), the folder
        and the environment (``env`` whole, else the context's with ``additional_env``)."""
        import shlex

        prefix = shlex.split(perform(self.prefix, context)) if self.prefix else []
        words = [perform(word, context) for word in self.cmd]
        words += [perform(argument, context) for argument in self.arguments]
        self.final_cmd = prefix + words
        name = perform(self.name, context) if self.name else os.path.basename(words[0])
        self.final_name = name
        self.final_cwd = perform(self.cwd, context) if self.cwd else None
        if self.env is not None:
            env = {perform(k, context): perform(v, context) for k, v in self.env.items()}
        else:
            env = dict(context.environment)
        for key, value in (self.additional_env or {}).items():
            env[perform(key, context)] = perform(value, context)
        self.final_env = env
