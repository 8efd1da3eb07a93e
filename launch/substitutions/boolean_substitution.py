"""launch.substitutions' boolean substitutions: NotSubstitution (``$(not X)``),
AndSubstitution (``$(and X Y)``), OrSubstitution (``$(or X Y)``), AllSubstitution and
AnySubstitution. Each argument is read as a condition (launch.conditions)."""

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
from launch.substitutions._args import arguments


def _truth(value: Any, context: LaunchContext, where: str, what: str) -> bool:
    from launch.conditions.evaluate_condition_expression_impl import condition_truth

    return condition_truth(perform(value, context), where, f"{what} argument")


@expose_substitution("not")
class NotSubstitution(Substitution):
    def __init__(self, value: SomeSubstitutionsType) -> None:
        super().__init__()
        self.value = normalize_to_list_of_substitutions(value)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        return cls, {"value": arguments("not", data, 1, 1)[0]}

    def describe(self) -> str:
        return f"NotSubstitution({self.value})"

    def perform(self, context: LaunchContext) -> str:
        return str(not _truth(self.value, context, self.where, "$(not)")).lower()


class _ManySubstitution(Substitution):
    """All (``combine=all``) or any (``any``) of its arguments."""

    name = ""
    combine = staticmethod(all)

    def __init__(self, *args: SomeSubstitutionsType) -> None:
        super().__init__()
        self.args = [normalize_to_list_of_substitutions(arg) for arg in args]

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        return cls, {"args": list(data or [])}

    def describe(self) -> str:
        return f"{type(self).__name__}({', '.join(map(str, self.args))})"

    def perform(self, context: LaunchContext) -> str:
        values = [_truth(arg, context, self.where, f"$({self.name})") for arg in self.args]
        return str(type(self).combine(values)).lower()


class AllSubstitution(_ManySubstitution):
    name, combine = "all", staticmethod(all)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        return _Positional, {"kind": cls, "args": list(data or [])}


class AnySubstitution(_ManySubstitution):
    name, combine = "any", staticmethod(any)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        return _Positional, {"kind": cls, "args": list(data or [])}


def _Positional(kind: type, args: list[Any]) -> Substitution:
    return kind(*args)


@expose_substitution("and")
class AndSubstitution(_ManySubstitution):
    name, combine = "and", staticmethod(all)

    def __init__(self, left: SomeSubstitutionsType, right: SomeSubstitutionsType) -> None:
        super().__init__(left, right)
        self.left, self.right = self.args

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        left, right = arguments(cls.name, data, 2, 2)
        return cls, {"left": left, "right": right}


@expose_substitution("or")
class OrSubstitution(AndSubstitution):
    name, combine = "or", staticmethod(any)


expose_substitution("all")(AllSubstitution)
expose_substitution("any")(AnySubstitution)
