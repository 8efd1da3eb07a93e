"""What the actions share: numbers and flags read from text or substitutions, a
step performed when its event happens, the checks of a front-end's attributes."""

from __future__ import annotations

import math
import shlex
from collections.abc import Callable, Iterable
from typing import Any

from launch._base import Action, SomeSubstitutionsType, perform
from launch.launch_context import LaunchContext
from launch_foundation.declarations import (
    MAX_SECONDS,
    Step,
    When,
    shown_line,
)
from launch_foundation.errors import LaunchError

DEFAULT_OUTPUT_FORMAT = "[{this.process_description.final_name}] {line}"


def seconds(value: Any, context: LaunchContext, where: str, what: str) -> float:
    """A period or a timeout: a number, or text or substitutions that give one."""
    text = value if isinstance(value, (int, float)) else perform(value, context)
    try:
        number = float(text)
    except ValueError:
        number = math.nan
    if not math.isfinite(number) or number < 0 or number > MAX_SECONDS:
        raise LaunchError(f"{where}: {what} must be 0 to {MAX_SECONDS:.0f} seconds, not {text!r}")
    return number


def flag(value: Any, context: LaunchContext) -> bool:
    if isinstance(value, bool):
        return value
    return perform(value, context).strip().lower() in ("true", "1")


class NameValueAction(Action):
    """An action that sets NAME to VALUE (`<let>`, `<set_env>`, launch_ros's `<set_parameter>`):
    their one constructor and front-end parse; each says in execute what setting means."""

    def __init__(self, name: SomeSubstitutionsType, value: SomeSubstitutionsType, **kw: Any):
        super().__init__(**kw)
        self.name, self.value = name, value

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["name"] = parser.parse_substitution(entity.get_attr("name"))
        kwargs["value"] = parser.parse_substitution(entity.get_attr("value"))
        return cls, kwargs


def env_name(action: Any, context: LaunchContext) -> str:
    """The variable an environment action names, refused where no environment can hold it."""
    name = perform(action.name, context)
    if not name or "=" in name or "\0" in name:
        raise action.error(f"invalid environment variable name {name!r}")
    return name


def lazy_step(
    action: Action, context: LaunchContext, text: Callable[[], str], kind: str = "log"
) -> Step:
    """A step of an event handler whose text is performed when the event happens, with the
    event in ``context.locals``; a substitution that fails then shuts the launch down with
    its one line at ERROR, as it ends ros2 launch (status 1)."""

    def call(info: dict) -> list[Step]:
        from launch.event_handlers import first_event
        from launch.events import event_from

        if not first_event(context, info):
            return []
        context.locals["event"] = event_from(info)
        try:
            return [Step(context.when, kind, text(), where=action.where)]
        except LaunchError as error:
            return [Step(context.when, "error", str(error), where=action.where)]

    return Step(context.when, "call", kind, call=call, where=action.where)


def given_value(value: Any, context: LaunchContext) -> Any:
    """A number or its text, None if not given (a front-end's attribute that is empty)."""
    if value is None or isinstance(value, (int, float)):
        return value
    return perform(value, context) or None


def enabled(value: Any, context: LaunchContext) -> bool:
    """Whether a front-end's child element a value came from holds (its if/unless)."""
    check = getattr(value, "enabled", None)
    return check(context) if check is not None else True


def command_words(values: Iterable[Any], context: LaunchContext) -> list[str]:
    """A command line's words: each value one word, a front-end's command-line attribute
    (FrontendWords) split as a shell would."""
    words: list[str] = []
    for value in values:
        split = getattr(value, "words", None)
        words += split(context) if split is not None else [perform(value, context)]
    return words


def frontend_attr(
    entity: Any,
    name: str,
    check: Callable[[str, Any], str] | None = None,
    kind: Any = None,
    optional: bool = True,
) -> Any:
    """Attribute ``name`` of a front-end's entity as text performed when the action needs it
    and then checked (``check``, at the entity's line); None if not written."""
    from launch.frontend.frontend_text import FrontendText

    text = entity.get_attr(name, optional=optional)
    return None if text is None else (kind or FrontendText)(text, entity.element, check)


def _non_empty_cmd(text: str, element: Any) -> str:
    try:
        words = shlex.split(text)
    except ValueError as error:  # No closing quotation
        raise element.error(f"cmd={text!r}: {error}") from None
    if not words:
        raise element.error("<executable> needs a non-empty 'cmd'")
    return text


def _output_check(text: str, element: Any) -> str:
    if text not in ("screen", "log", "both"):
        raise element.error(f"output={text!r}; use one of screen, log, both")
    return text


def _flag_check(name: str) -> Callable[[str, Any], str]:
    def check(text: str, element: Any) -> str:
        from launch_foundation.substitutions import to_bool

        return "true" if to_bool(text, element, f"{name!r}") else "false"

    return check


def number_check(name: str, kind: type = float) -> Callable[[str, Any], str]:
    """A front-end's number: not negative (an int may be -1: for ever), at most a day."""

    def check(text: str, element: Any) -> str:
        if not text:
            return text
        try:
            value = kind(text)
        except ValueError:
            value = None
        # nan and inf would make the supervisor's deadlines unreachable: refuse them too.
        bad = value is None or not math.isfinite(value) or value < 0
        if bad and not (kind is int and value == -1):
            raise element.error(f"{name!r} must be a non-negative number, not {text!r}")
        if kind is float and value > MAX_SECONDS:
            raise element.error(f"{name!r} is {text} s; at most {MAX_SECONDS:.0f} s (a day)")
        return text

    return check


def _env_name_check(name: str, element: Any) -> str:
    if not name or "=" in name or "\0" in name:
        raise element.error(f"invalid environment variable name {name!r}")
    return name


def checked_output_format(output_format: Any, where: str) -> str:
    """ExecuteProcess's output_format, tried on a sample line now: a field it cannot fill
    ({nme}) is the launch file's error, not a failure of each line later."""
    if not isinstance(output_format, str):
        raise LaunchError(
            f"{where}: output_format must be text, not {type(output_format).__name__}"
        )
    try:
        shown_line(output_format, "name", "line")
    except (AttributeError, IndexError, KeyError, ValueError) as error:
        raise LaunchError(
            f"{where}: output_format {output_format!r} cannot be formatted: {error!r} (it can use "
            "{line} and {this.process_description.final_name})"
        ) from None
    return output_format


def _process_details(custom_env: bool, info: dict[str, Any]) -> list[Step]:
    """log_cmd's line, from what the supervisor reports when the process starts."""
    text = "process details: cmd=[{}], cwd='{}', custom_env?={}".format(
        ", ".join(info.get("cmd", [])), info.get("cwd"), custom_env
    )
    return [Step(When("start"), "log", text)]


def normalize_actions(value: Any) -> list[Any]:
    if value is None:
        return []
    return list(value) if isinstance(value, (list, tuple)) else [value]
