"""The Python launch API's core (ros2/launch's LaunchDescriptionEntity, Action, Substitution,
TextSubstitution, Condition, EventHandler), written for this project's launcher; the context
they are executed in is launch.launch_context's.

A Python launch file builds these objects, and the markup front-ends build the same ones
(launch.frontend); the model's executor (``LaunchContext.visit``) executes them into a plan:
executing an action hands a process or a step to the context's sink
(``launch_foundation.declarations.PlanSink``) instead of doing it at once. Each entity remembers the
line of the launch file that created it, so an error names the user's file:line, never a line
in here.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from launch_foundation.declarations import Step, When
from launch_foundation.errors import LaunchError
from launch_foundation.parse import Element

# The folders of the stand-in: frames in them are not the user's.
_STACK = ("launch", "launch_ros", "launch_xml", "launch_yaml", "launch_foundation", "launcher")
_OURS = tuple(str(Path(__file__).resolve().parent.parent / name) + os.sep for name in _STACK)


def is_ours(filename: str) -> bool:
    return filename.startswith(_OURS) or filename.startswith("<frozen")


_LAUNCHER = _OURS[-1]


def caller_where() -> str:
    """file:line of the first frame outside the stand-in: the launch file's line. An entity a
    front-end builds (the launcher's frames come first) is told its file:line by it."""
    frame = sys._getframe(1)
    while frame is not None and is_ours(frame.f_code.co_filename):
        if frame.f_code.co_filename.startswith(_LAUNCHER):
            return "<launch file>"  # not the whole stack's walk for each of them
        frame = frame.f_back
    if frame is None:
        return "<launch file>"
    return f"{frame.f_code.co_filename}:{frame.f_lineno}"


def element_at(where: str) -> Element:
    """A file:line as the front-ends' helpers take it (for their errors)."""
    file, _, line = where.rpartition(":")
    if not line.isdigit():
        file, line = where, "0"
    return Element("launch", {}, Path(file), int(line))


class SubstitutionFailure(LaunchError):
    """A substitution that cannot be performed (launch.substitutions.SubstitutionFailure):
    one line, naming the launch file's file:line where known."""


class LaunchDescriptionEntity:
    """Anything a LaunchDescription holds."""

    def __init__(self) -> None:
        self.where = caller_where()

    def error(self, message: str) -> LaunchError:
        return LaunchError(f"{self.where}: {message}")

    def execute(self, context: Any) -> list[LaunchDescriptionEntity] | None:
        return None

    def describe(self) -> str:
        raise NotImplementedError(f"{type(self).__name__}.describe()")

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return []

    def describe_conditional_sub_entities(self) -> list[tuple[str, list[Any]]]:
        return []

    def visit(self, context: Any) -> list[LaunchDescriptionEntity] | None:
        """ros2/launch's visit of an entity that is no action: nothing to do."""
        return None

    def get_asyncio_future(self) -> None:
        return None


class FrontendEntity(LaunchDescriptionEntity):
    """An element a front-end (launch XML or YAML) parsed, executed where the description
    reaches it: ``handle`` reads the element in the context's scope (its tag's handler)."""

    def __init__(self, handle: Callable[[Any], None], where: str) -> None:
        super().__init__()
        self.handle, self.where = handle, where

    def execute(self, context: Any) -> None:
        self.handle(context)


class Condition:
    """When an action runs (launch.Condition): ``predicate(context)``, else a subclass's
    ``evaluate``."""

    def __init__(self, *, predicate: Callable[[Any], bool] | None = None) -> None:
        self.where = caller_where()
        self._predicate = predicate

    def evaluate(self, context: Any) -> bool:
        return bool(self._predicate(context)) if self._predicate is not None else False

    def describe(self) -> str:
        return f"{type(self).__name__}()"


class Action(LaunchDescriptionEntity):
    """An action, run only if its condition holds (launch.Action)."""

    def __init__(self, *, condition: Condition | None = None) -> None:
        super().__init__()
        self.condition = condition

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        """What every tag of a markup front-end has (launch.frontend): ``if``/``unless``. Each
        action's own parse adds its attributes to these keyword arguments."""
        condition = parser.parse_condition(entity)
        kwargs: dict[str, Any] = {} if condition is None else {"condition": condition}
        return cls, kwargs

    def visit(self, context: Any) -> list[LaunchDescriptionEntity] | None:
        """Execute this action into the plan if its condition holds: the entities it returns,
        for the executor (LaunchContext.visit) to visit next, as ros2/launch's visit."""
        if self.condition is not None and not self.condition.evaluate(context):
            return None
        context.state.executed[id(self)] = self
        return self.execute(context)

    def describe(self) -> str:
        return f"{type(self).__name__}(...)"

    def step_when_returned(self, when: When, context: Any) -> Step | None:
        """What this action does when an event handler's function returns it, as the event
        happens: a step, or None if it cannot happen then (the plan's processes are fixed)."""
        return None


class Substitution:
    """A value known when the launch runs (launch.Substitution)."""

    where = "<launch file>"  # a subclass that skips __init__ still has one

    def __init__(self) -> None:
        self.where = caller_where()

    def perform(self, context: Any) -> str:
        raise NotImplementedError

    def describe(self) -> str:
        return type(self).__name__ + "(...)"

    def __repr__(self) -> str:
        return self.describe()

    def error(self, message: str) -> LaunchError:
        return LaunchError(f"{self.where}: {message}")


SomeSubstitutionsType = str | Substitution | Iterable[str | Substitution]


class TextSubstitution(Substitution):
    """Text as it is (launch.substitutions.TextSubstitution)."""

    def __init__(self, *, text: str) -> None:
        super().__init__()
        if not isinstance(text, str):
            raise TypeError(f"TextSubstitution expected text, got {type(text).__name__}")
        self.text = text

    def perform(self, context: Any) -> str:
        return self.text

    def describe(self) -> str:
        return repr(self.text)


def normalize_to_list_of_substitutions(subs: Any) -> list[Substitution]:
    """Text, a substitution, or a list of them, as a list of substitutions (text becomes a
    TextSubstitution; launch.utilities.normalize_to_list_of_substitutions)."""
    return [TextSubstitution(text=item) if isinstance(item, str) else item
            for item in normalize(subs)]  # fmt: skip


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
            f"{where or caller_where()}: expected text or substitutions, got {type(value).__name__}"
        ) from None
    out: list[Substitution | str] = []
    for item in items:
        out += normalize(item, where)
    return out


def perform(value: Any, context: Any) -> str:
    """The text of a substitutions value, as the launch sees it now."""
    if value is None:
        return ""
    return "".join(
        item if isinstance(item, str) else item.perform(context) for item in normalize(value)
    )


class EventHandler:
    """Base of launch.event_handlers: what runs when an event happens. ``matcher(event)``
    says whether it is one for this handler; ``entities`` are what handling it gives."""

    def __init__(
        self,
        *,
        matcher: Callable[[Any], bool] | None = None,
        entities: Any = None,
        handle_once: bool = False,
    ) -> None:
        self.where = caller_where()
        self.matcher = matcher
        self.entities = entities
        self.handle_once = handle_once

    def matches(self, event: Any) -> bool:
        return bool(self.matcher(event)) if self.matcher is not None else False

    def describe(self) -> tuple[str, list[Any]]:
        return f"{type(self).__name__}(matcher=...)", []

    def handle(self, event: Any, context: Any) -> Any:
        """The event in ``context.locals.event``; the entities; once only if ``handle_once``."""
        context.extend_locals({"event": event})
        if self.handle_once:
            context.unregister_event_handler(self)
        return self.entities
