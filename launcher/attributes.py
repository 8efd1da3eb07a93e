"""A markup tag's attributes read in its scope: ``$(...)`` performed, then taken as text, words,
a flag, a namespace or a number; ``if``/``unless`` decided. What both markup front-ends
(launcher/ros1.py, launcher/ros2_markup.py) and the loader read the same way. The ROS 2
formats' ``$(...)`` are read by launch.frontend's scanner and performed in a LaunchContext of
the scope, as the model's actions perform theirs (one engine for ROS 2 text); roslaunch's by
launcher/ros1_substitutions.py.
"""

from __future__ import annotations

import shlex
from typing import TYPE_CHECKING, Any

from launch_foundation.naming import namespace_under
from launch_foundation.parse import Element
from launch_foundation.substitutions import to_bool
from launcher.ros1_substitutions import substitute

if TYPE_CHECKING:
    from launcher.scope import Scope


def text(element: Element, name: str, scope: Scope, default: str | None = None) -> str:
    """Attribute ``name`` with its substitutions performed (``default`` if absent; without a
    default, an absent attribute is an error at the tag's line)."""
    if name in element.attrs:
        return perform(element.attrs[name], scope, element)
    if default is None:
        raise element.error(f"<{element.tag}> needs a {name!r} attribute")
    return default


def perform(value: str, scope: Scope, element: Element) -> str:
    """``value``, an attribute's text at ``element``, with its ``$(...)`` performed by the
    engine of the scope's format."""
    if scope.fmt == "ros2":
        from launch.frontend.parse_substitution import parse_at, perform_capped

        where = element.where
        return perform_capped(parse_at(value, where), scope.loader.context(scope), where)
    return substitute(value, scope, element)


def words(element: Element, name: str, scope: Scope) -> list[str]:
    """An attribute split into words as a shell would (args, cmd, launch-prefix)."""
    value = text(element, name, scope, "")
    try:
        return shlex.split(value)
    except ValueError as error:  # No closing quotation
        raise element.error(f"{name.replace('_', '-')}={value!r}: {error}") from None


def flag(element: Element, name: str, scope: Scope) -> bool:
    return to_bool(text(element, name, scope, "false"), element, f"{name!r}")


def number(element: Element, name: str, scope: Scope, kind: type = float) -> Any:
    """An attribute's number, by the rule ExecuteProcess's front-end parse keeps."""
    from launch.actions import number_check

    value = number_check(name, kind)(text(element, name, scope, ""), element)
    return kind(value) if value else None


def enabled(element: Element, scope: Scope) -> bool:
    """The tag's ``if`` or ``unless``, performed in its scope: in the ROS 2 formats by the
    model's own reading (launch.frontend's frontend_enabled, launch.conditions'), in ROS 1's
    by roslaunch's."""
    if scope.fmt == "ros2":
        if "if" not in element.attrs and "unless" not in element.attrs:
            return True
        from launch.frontend.frontend_text import frontend_enabled

        return frontend_enabled(element, scope.loader.context(scope))
    if "if" in element.attrs:
        return to_bool(text(element, "if", scope), element, "'if'")
    if "unless" in element.attrs:
        return not to_bool(text(element, "unless", scope), element, "'unless'")
    return True


def namespace(element: Element, name: str, scope: Scope) -> str:
    """Attribute ``name`` as a namespace under the scope's."""
    value = text(element, name, scope)
    full = namespace_under(scope.namespace, value)
    if full is None:
        raise element.error(f"invalid namespace {value!r}")
    return full
