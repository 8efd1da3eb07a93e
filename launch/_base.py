"""The Python launch API's core (ros2/launch's LaunchDescriptionEntity, Action, Substitution,
Condition, EventHandler, LaunchContext), written for this project's launcher.

A Python launch file builds these objects; ``launcher/python_files.py`` calls its
``generate_launch_description()`` and executes the entities into the same plan the XML and
YAML front-ends build (``launcher/resolve.py``): executing an action adds a process or a step
to the plan instead of doing it at once. Each entity remembers the line of the launch file that
created it, so an error names the user's file:line, never a line in here.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from launcher import LaunchError
from launcher.declarations import Step, When

if TYPE_CHECKING:
    from launcher.resolve import Scope

# The folders of the stand-in: frames in them are not the user's.
_OURS = tuple(
    str(Path(__file__).resolve().parent.parent / name) + os.sep
    for name in ("launch", "launch_ros", "launch_xml", "launch_yaml", "launcher")
)


def is_ours(filename: str) -> bool:
    return filename.startswith(_OURS) or filename.startswith("<frozen")


def caller_where() -> str:
    """file:line of the first frame outside the stand-in: the launch file's line."""
    frame = sys._getframe(1)
    while frame is not None and is_ours(frame.f_code.co_filename):
        frame = frame.f_back
    if frame is None:
        return "<launch file>"
    return f"{frame.f_code.co_filename}:{frame.f_lineno}"


class LaunchDescriptionEntity:
    """Anything a LaunchDescription holds."""

    def __init__(self) -> None:
        self.where = caller_where()

    def error(self, message: str) -> LaunchError:
        return LaunchError(f"{self.where}: {message}")

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        return None

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return []


class Condition:
    """When an action runs (launch.conditions)."""

    def __init__(self) -> None:
        self.where = caller_where()

    def evaluate(self, context: LaunchContext) -> bool:
        raise NotImplementedError


class Action(LaunchDescriptionEntity):
    """An action, run only if its condition holds (launch.Action)."""

    def __init__(self, *, condition: Condition | None = None) -> None:
        super().__init__()
        self.condition = condition

    def visit(self, context: LaunchContext) -> None:
        """Execute this action into the plan, with what it returns, if its condition holds."""
        if self.condition is not None and not self.condition.evaluate(context):
            return
        context.resolver.executed[id(self)] = self
        for entity in self.execute(context) or []:
            context.visit(entity)

    def step_when_returned(self, when: When, context: LaunchContext) -> Step | None:
        """What this action does when an event handler's function returns it, as the event
        happens: a step, or None if it cannot happen then (the plan's processes are fixed)."""
        return None


class Substitution:
    """A value known when the launch runs (launch.Substitution)."""

    def __init__(self) -> None:
        self.where = caller_where()

    def perform(self, context: LaunchContext) -> str:
        raise NotImplementedError

    def describe(self) -> str:
        return type(self).__name__ + "(...)"

    def error(self, message: str) -> LaunchError:
        return LaunchError(f"{self.where}: {message}")


SomeSubstitutionsType = str | Substitution | Iterable[str | Substitution]


def normalize(value: Any, where: str = "") -> list[Substitution | str]:
    """A substitutions value (text, a substitution, or a list of them) as a list."""
    if isinstance(value, (str, Substitution)):
        return [value]
    if isinstance(value, (int, float, Path)):
        return [str(value)]
    try:
        items = list(value)
    except TypeError:
        raise LaunchError(
            f"{where}: expected text or substitutions, got {type(value).__name__}"
        ) from None
    out: list[Substitution | str] = []
    for item in items:
        out += normalize(item, where)
    return out


def perform(value: Any, context: LaunchContext) -> str:
    """The text of a substitutions value, as the launch sees it now."""
    if value is None:
        return ""
    return "".join(
        item if isinstance(item, str) else item.perform(context) for item in normalize(value)
    )


class EventHandler:
    """Base of launch.event_handlers: what runs when an event of a process happens."""

    def __init__(self) -> None:
        self.where = caller_where()


class LaunchContext:
    """What actions and substitutions see: a scope of the launcher's resolver (launch
    configurations, namespace, remaps, parameters, environment) and, in an event handler, the
    event (``locals``)."""

    def __init__(self, scope: Scope, locals_: dict[str, Any] | None = None) -> None:
        self.scope = scope
        self.locals = dict(locals_ or {})

    @property
    def resolver(self) -> Any:
        return self.scope.resolver

    @property
    def launch_configurations(self) -> dict[str, str]:
        return self.scope.args

    @property
    def environment(self) -> dict[str, str]:
        env = dict(os.environ)
        for name, value in self.scope.env.items():
            if value is None:
                env.pop(name, None)
            else:
                env[name] = value
        return env

    def perform_substitution(self, substitution: Substitution) -> str:
        return substitution.perform(self)

    def extend_locals(self, values: dict[str, Any]) -> None:
        self.locals.update(values)

    def get_locals_as_dict(self) -> dict[str, Any]:
        return dict(self.locals)

    def child(self, **changes: Any) -> LaunchContext:
        return LaunchContext(self.scope.child(**changes), self.locals)

    def visit(self, entity: Any) -> None:
        """Execute one entity of a description, or refuse what is not one."""
        if isinstance(entity, Action):
            entity.visit(self)
        elif isinstance(entity, LaunchDescriptionEntity):
            for sub in entity.execute(self) or []:
                self.visit(sub)
        elif entity is not None:
            raise LaunchError(
                f"{caller_where()}: {type(entity).__name__} is not a launch action "
                "(a LaunchDescription holds actions: Node, ExecuteProcess, ...)"
            )
