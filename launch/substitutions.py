"""launch.substitutions: values known when the launch runs (launch configurations, paths,
environment variables, Python expressions, command output)."""

from __future__ import annotations

import math
import os
import shlex
import shutil
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from launch._base import (
    LaunchContext,
    SomeSubstitutionsType,
    Substitution,
    caller_where,
    normalize,
    perform,
)
from launch._missing import module_getattr
from launch_foundation.parse import Element
from launch_foundation.substitutions import substitute, to_bool

__all__ = [
    "AndSubstitution", "AnonName", "Command", "EnvironmentVariable", "EqualsSubstitution",
    "FindExecutable", "IfElseSubstitution", "LaunchConfiguration", "LocalSubstitution",
    "NotEqualsSubstitution", "NotSubstitution", "OrSubstitution", "PathJoinSubstitution",
    "PythonExpression", "Substitution", "TextSubstitution", "ThisLaunchFile",
    "ThisLaunchFileDir",
]  # fmt: skip


class FrontendText(Substitution):
    """An attribute's text as a front-end (launch XML or YAML) wrote it, its $(...) performed
    when the action that holds it needs the value (launch's parse_substitution, lazily)."""

    def __init__(
        self, text: str, element: Element, check: Callable[[str, Element], str] | None = None
    ) -> None:
        super().__init__()
        self.text, self.element, self.where = text, element, element.where
        self.check = check  # the attribute's own check of its value, at its element's line

    def perform(self, context: LaunchContext) -> str:
        value = substitute(self.text, context.frontend_scope, self.element)
        return self.check(value, self.element) if self.check else value

    def enabled(self, context: LaunchContext) -> bool:
        """Whether the element this text is an attribute of holds (its ``if``/``unless``):
        a child of a <node> or <executable> read into the action's arguments."""
        return frontend_enabled(self.element, context)


class FrontendWords(FrontendText):
    """An attribute that is a command line (cmd, args, ros_args, launch-prefix): its words
    are split as a shell would, after its $(...) are performed."""

    def words(self, context: LaunchContext) -> list[str]:
        return shlex.split(self.perform(context))


def split_words(name: str) -> Callable[[str, Element], str]:
    """FrontendWords' check: text a shell can split (the attribute ``name``)."""

    def check(text: str, where: Element) -> str:
        try:
            shlex.split(text)
        except ValueError as error:  # No closing quotation
            raise where.error(f"{name.replace('_', '-')}={text!r}: {error}") from None
        return text

    return check


def frontend_enabled(element: Element, context: LaunchContext) -> bool:
    """An element's ``if``/``unless``, performed now in the launch's scope."""
    scope = context.frontend_scope
    if "if" in element.attrs:
        return to_bool(substitute(element.attrs["if"], scope, element), element, "'if'")
    if "unless" in element.attrs:
        return not to_bool(substitute(element.attrs["unless"], scope, element), element, "'unless'")
    return True


class TextSubstitution(Substitution):
    def __init__(self, *, text: str) -> None:
        super().__init__()
        self.text = text

    def perform(self, context: LaunchContext) -> str:
        return self.text


class LaunchConfiguration(Substitution):
    """The value of a launch argument or launch configuration."""

    def __init__(self, variable_name: SomeSubstitutionsType, *, default: Any = None) -> None:
        super().__init__()
        self.variable_name = variable_name
        self.default = default

    def perform(self, context: LaunchContext) -> str:
        name = perform(self.variable_name, context)
        context.state.configurations_read.add(name)
        if name in context.launch_configurations:
            return context.launch_configurations[name]
        if self.default is not None:
            return perform(self.default, context)
        known = ", ".join(sorted(context.launch_configurations)) or "none"
        raise self.error(f"launch configuration {name!r} is not set (set here: {known})")


class EnvironmentVariable(Substitution):
    def __init__(self, name: SomeSubstitutionsType, *, default_value: Any = None) -> None:
        super().__init__()
        self.name = name
        self.default_value = default_value

    def perform(self, context: LaunchContext) -> str:
        name = perform(self.name, context)
        value = context.environment.get(name)
        if value is not None:
            return value
        if self.default_value is None:
            raise self.error(f"environment variable {name} is not set")
        return perform(self.default_value, context)


class PathJoinSubstitution(Substitution):
    def __init__(self, substitutions: Any) -> None:
        super().__init__()
        self.substitutions = list(substitutions)

    def perform(self, context: LaunchContext) -> str:
        return os.path.join(*(perform(part, context) for part in self.substitutions))

    def __truediv__(self, other: Any) -> PathJoinSubstitution:
        return PathJoinSubstitution([self, other])


class PythonExpression(Substitution):
    """eval() of the expression's text, with the math module's names (a Python launch file
    runs code anyway)."""

    def __init__(self, expression: SomeSubstitutionsType, python_modules: Any = ("math",)) -> None:
        super().__init__()
        self.expression = expression
        self.python_modules = python_modules

    def perform(self, context: LaunchContext) -> str:
        text = perform(self.expression, context)
        names: dict[str, Any] = {}
        for module in normalize(self.python_modules, self.where):
            name = perform(module, context)
            imported = __import__(name)
            names[name] = imported
            if name == "math":
                names.update({k: getattr(math, k) for k in dir(math) if not k.startswith("_")})
        try:
            return str(eval(text, names))
        except Exception as error:
            raise self.error(f"PythonExpression {text!r} failed: {error}") from None


class FindExecutable(Substitution):
    def __init__(self, *, name: SomeSubstitutionsType) -> None:
        super().__init__()
        self.name = name

    def perform(self, context: LaunchContext) -> str:
        name = perform(self.name, context)
        found = shutil.which(name) or shutil.which(name, path=os.path.dirname(sys.executable))
        if found is None:
            raise self.error(f"executable {name!r} not found on the PATH")
        return found


class Command(Substitution):
    """The output of a command (its stderr fails it, as ros2 launch's default)."""

    def __init__(self, command: SomeSubstitutionsType, *, on_stderr: str = "fail") -> None:
        super().__init__()
        self.command = command
        self.on_stderr = on_stderr

    def perform(self, context: LaunchContext) -> str:
        from launch_foundation.substitutions import run_command

        words = [perform(part, context) for part in normalize(self.command, self.where)]
        text = " ".join(words) if len(words) > 1 else words[0]
        return run_command(
            text, self.error, f"Command {text!r}", context.environment, self.on_stderr
        )


class AnonName(Substitution):
    def __init__(self, name: SomeSubstitutionsType) -> None:
        super().__init__()
        self.name = name

    def perform(self, context: LaunchContext) -> str:
        return context.anon(perform(self.name, context))


class ThisLaunchFile(Substitution):
    def perform(self, context: LaunchContext) -> str:
        return str(context.launch_file)


class ThisLaunchFileDir(Substitution):
    def perform(self, context: LaunchContext) -> str:
        return str(context.launch_file.parent)


class LocalSubstitution(Substitution):
    """A value of the event an event handler runs for: ``event.reason``, ``event.returncode``."""

    def __init__(self, expression: str, description: str | None = None) -> None:
        super().__init__()
        self.expression = expression

    def perform(self, context: LaunchContext) -> str:
        if not context.locals:
            raise self.error(f"LocalSubstitution({self.expression!r}) outside an event handler")
        try:
            return str(eval(self.expression, {}, context.locals))
        except Exception as error:
            raise self.error(f"LocalSubstitution({self.expression!r}): {error}") from None


class NotSubstitution(Substitution):
    def __init__(self, value: SomeSubstitutionsType) -> None:
        super().__init__()
        self.value = value

    def perform(self, context: LaunchContext) -> str:
        return str(not to_bool(perform(self.value, context), self.where, "NotSubstitution")).lower()


class AndSubstitution(Substitution):
    def __init__(self, left: SomeSubstitutionsType, right: SomeSubstitutionsType) -> None:
        super().__init__()
        self.left, self.right = left, right

    def perform(self, context: LaunchContext) -> str:
        values = [to_bool(perform(v, context), self.where, "AndSubstitution")
                  for v in (self.left, self.right)]  # fmt: skip
        return str(all(values)).lower()


class OrSubstitution(AndSubstitution):
    def perform(self, context: LaunchContext) -> str:
        values = [to_bool(perform(v, context), self.where, "OrSubstitution")
                  for v in (self.left, self.right)]  # fmt: skip
        return str(any(values)).lower()


class EqualsSubstitution(Substitution):
    def __init__(self, left: Any, right: Any) -> None:
        super().__init__()
        self.left, self.right = left, right

    def perform(self, context: LaunchContext) -> str:
        return str(perform(self.left, context) == perform(self.right, context)).lower()


class NotEqualsSubstitution(EqualsSubstitution):
    def perform(self, context: LaunchContext) -> str:
        return str(perform(self.left, context) != perform(self.right, context)).lower()


class IfElseSubstitution(Substitution):
    def __init__(self, condition: Any, if_value: Any = "", else_value: Any = "") -> None:
        super().__init__()
        self.condition, self.if_value, self.else_value = condition, if_value, else_value

    def perform(self, context: LaunchContext) -> str:
        chosen = to_bool(perform(self.condition, context), self.where, "IfElseSubstitution")
        return perform(self.if_value if chosen else self.else_value, context)


def _path_text(value: Any) -> Path:
    return Path(value)


__getattr__ = module_getattr("launch.substitutions", lambda: __all__)
_ = caller_where  # re-exported for the other modules of the API
