"""The registries of parse methods: a tag (or a substitution's name) -> the function that
builds its action (substitution) from an Entity. A tag is defined by the one method exposed
for it."""

from __future__ import annotations

import inspect
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

from launch_foundation.errors import LaunchError

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser

action_parse_methods: dict[str, Callable[..., tuple[type, dict[str, Any]]]] = {}
substitution_parse_methods: dict[str, Callable[..., tuple[type, dict[str, Any]]]] = {}


def _expose(name: str, registry: dict[str, Any], kind: str) -> Callable[[Any], Any]:
    def register(exposed: Any) -> Any:
        if inspect.isclass(exposed):
            method = getattr(exposed, "parse", None)
            if not inspect.ismethod(method):
                raise RuntimeError(f"{exposed.__name__} has no classmethod 'parse' to expose")
        elif inspect.isfunction(exposed):
            method = exposed
        else:
            raise RuntimeError(f"the {kind} parser of {name!r} is not a function or a class")
        known = registry.get(name)
        if known is not None and getattr(known, "__wrapped__", known) != method:
            raise RuntimeError(f"two {kind} parse methods exposed for {name!r}")
        if kind == "action":  # an attribute nobody read is a typo: refused, as launch does

            def checked(entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
                result = method(entity, parser)
                entity.assert_entity_completely_parsed()
                return result

            checked.__wrapped__ = method  # type: ignore[attr-defined]
            registry[name] = checked
        else:
            registry[name] = method
        return exposed

    return register


def expose_action(name: str) -> Callable[[Any], Any]:
    """Decorator: the class's ``parse(entity, parser) -> (action class, kwargs)`` (or the
    function itself) builds the action of tag ``name``."""
    return _expose(name, action_parse_methods, "action")


def expose_substitution(name: str) -> Callable[[Any], Any]:
    """Decorator: ``parse(args) -> (substitution class, kwargs)`` for ``$(name args...)``."""
    return _expose(name, substitution_parse_methods, "substitution")


def instantiate_action(entity: Entity, parser: Parser) -> Any:
    """The action of ``entity``, by the parse method exposed for its tag."""
    method = action_parse_methods.get(entity.type_name)
    if method is None:
        known = ", ".join(f"<{name}>" for name in sorted(action_parse_methods))
        raise LaunchError(f"{_where(entity)}unknown tag <{entity.type_name}>; known: {known}")
    action_type, kwargs = method(entity, parser)
    action = action_type(**kwargs)
    where = getattr(entity, "where", None)
    if where:  # its errors name the file's line
        action.where = where
    return action


def instantiate_substitution(type_name: str, args: Iterable[Any] | None = None) -> Any:
    """The substitution ``$(type_name args...)`` by the parse method its class exposed; each
    argument a list of substitutions."""
    method = substitution_parse_methods.get(type_name)
    if method is None:
        _load_substitutions()
        method = substitution_parse_methods.get(type_name)
    if method is None:
        known = ", ".join(f"$({name})" for name in sorted(substitution_parse_methods))
        raise LaunchError(f"unknown substitution $({type_name}); known here: {known}")
    substitution_type, kwargs = method(list(args or []))
    return substitution_type(**kwargs)


# The modules whose substitutions expose their names, loaded by name as ros2/launch loads
# its 'launch.frontend.launch_extension' entry points.
SUBSTITUTION_MODULES = ("launch.substitutions", "launch_ros.substitutions")


def _load_substitutions() -> None:
    import importlib

    for name in SUBSTITUTION_MODULES:
        importlib.import_module(name)


def _where(entity: Entity) -> str:
    where = getattr(entity, "where", None)
    return f"{where}: " if where else ""
