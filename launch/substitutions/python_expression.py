"""launch.substitutions.PythonExpression (``$(eval EXPRESSION [MODULES])``)."""

from __future__ import annotations

import importlib
import math
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
from launch.substitutions._args import arguments, joined
from launch.substitutions.substitution_failure import SubstitutionFailure


class PythonExpressionNameError(SubstitutionFailure, NameError):
    """The expression names something its modules do not give (a NameError, as ros2 launch
    raises it, with the launch file's line)."""


@expose_substitution("eval")
class PythonExpression(Substitution):
    """``eval`` of the performed expression with the given modules (``math`` by default,
    its names usable bare: ``ceil(1.6)``). A front-end's ``$(eval)`` runs no code unless the
    user passed --allow-code: values and operators are read without Python's eval."""

    def __init__(
        self,
        expression: SomeSubstitutionsType,
        python_modules: Any = ("math",),
        *,
        frontend: bool = False,
    ) -> None:
        super().__init__()
        self.expression = normalize_to_list_of_substitutions(expression)
        if isinstance(python_modules, (str, Substitution)):
            python_modules = [python_modules]
        self.python_modules = [
            normalize_to_list_of_substitutions(module) for module in python_modules
        ]
        self.frontend = frontend

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        data = arguments("eval", data, 1, 100)
        if len(data) > 2:  # unquoted words: one expression
            data = [joined(data)]
        kwargs: dict[str, Any] = {"expression": data[0], "frontend": True}
        if len(data) == 2:  # "math, sys": a comma-separated list, performed when evaluated
            kwargs["python_modules"] = [_ModuleList(data[1])]
        return cls, kwargs

    def describe(self) -> str:
        expression = "".join(s.describe().strip("'") for s in self.expression)
        modules = ", ".join(
            repr("".join(s.describe().strip("'") for s in module)) for module in self.python_modules
        )
        return f"PythonExpr({expression!r}, [{modules}])"

    def module_names(self, context: LaunchContext) -> list[str]:
        names: list[str] = []
        for module in self.python_modules:
            for name in perform(module, context).split(","):
                if name.strip():
                    names.append(name.strip())
        return names

    def perform(self, context: LaunchContext) -> str:
        text = perform(self.expression, context)
        names: dict[str, Any] = {}
        for name in self.module_names(context):
            try:
                names[name] = importlib.import_module(name)
            except ImportError as error:
                raise SubstitutionFailure(f"{self.where}: PythonExpression: {error}") from None
            if name == "math":
                names.update({k: getattr(math, k) for k in dir(math) if not k.startswith("_")})
        if self.frontend:
            return self._frontend_value(text, names, context)
        return self._eval(text, names)

    def _eval(self, text: str, names: dict[str, Any]) -> str:
        try:
            return str(eval(text, names))
        except NameError as error:
            raise PythonExpressionNameError(
                f"{self.where}: PythonExpression {text!r} failed: {error}"
            ) from None
        except Exception as error:
            raise SubstitutionFailure(
                f"{self.where}: PythonExpression {text!r} failed: {error}"
            ) from None

    def _frontend_value(self, text: str, names: dict[str, Any], context: LaunchContext) -> str:
        """$(eval): read by launch_foundation.expressions without running code; code only with the
        user's --allow-code."""
        from launch_foundation.errors import CodeRefused
        from launch_foundation.expressions import BUILTINS, MATH, NeedsCode, evaluate

        safe = {**(MATH if "math" in names else {}), **BUILTINS}
        try:
            return str(evaluate(text, safe))
        except NeedsCode as part:
            if not context.allow_code:
                raise CodeRefused(
                    f"{self.where}: $(eval {text}) runs code written in the launch file ({part})"
                ) from None
        except Exception as error:
            if not isinstance(error, NameError):
                raise SubstitutionFailure(f"{self.where}: $(eval {text}) failed: {error}") from None
        return self._eval(text, {**safe, **names})


class _ModuleList(Substitution):
    """$(eval)'s second argument: modules named with commas."""

    def __init__(self, parts: list[Any]) -> None:
        super().__init__()
        self.parts = parts

    def perform(self, context: LaunchContext) -> str:
        return perform(self.parts, context)

    def describe(self) -> str:
        return "".join(p.describe().strip("'") for p in self.parts)
