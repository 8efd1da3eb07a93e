"""launch.actions: what a Python launch file's LaunchDescription holds.

(About 800 lines: every action of launch.actions, about twenty small classes, in the one
module launch files import them from; ros2/launch keeps one file per action.)

Each action's ``execute`` adds to the launcher's plan: a process (ExecuteProcess, and
launch_ros's Node), a step (LogInfo, EmitEvent(Shutdown)), or a change to the scope the
following actions see (DeclareLaunchArgument, SetEnvironmentVariable, GroupAction, ...).
"""

from __future__ import annotations

import functools
import math
import os
import shlex
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from launch._base import (
    Action,
    Condition,
    EventHandler,
    LaunchContext,
    LaunchDescriptionEntity,
    SomeSubstitutionsType,
    Substitution,
    normalize,
    perform,
)
from launch._missing import module_getattr
from launch.event_handlers import OnProcessExit
from launch.events import Shutdown as ShutdownEvent
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action
from launch_foundation.declarations import (
    DEFAULT_RESPAWN_MAX_RETRIES,
    MAX_SECONDS,
    NodeDecl,
    Step,
    When,
    shown_line,
)
from launch_foundation.errors import LaunchError

__all__ = [
    "AppendEnvironmentVariable", "DeclareLaunchArgument", "EmitEvent", "ExecuteProcess",
    "GroupAction", "IncludeLaunchDescription", "LogInfo", "OpaqueFunction",
    "RegisterEventHandler", "ResetLaunchConfigurations", "SetEnvironmentVariable",
    "SetLaunchConfiguration", "Shutdown", "TimerAction", "UnsetEnvironmentVariable",
    "UnsetLaunchConfiguration",
]  # fmt: skip


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


@expose_action("arg")
class DeclareLaunchArgument(Action):
    """A launch argument: ``name:=value`` on the command line or from an includer, else its
    default."""

    def __init__(
        self,
        name: str,
        *,
        default_value: SomeSubstitutionsType | None = None,
        description: str | None = None,
        choices: Iterable[str] | None = None,
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        self.name = name
        self.default_value = default_value
        self.description = description
        self.choices = list(choices) if choices is not None else None

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["name"] = entity.get_attr("name")
        default = entity.get_attr("default", optional=True)
        if default is not None:
            kwargs["default_value"] = parser.parse_substitution(default)
        kwargs["description"] = entity.get_attr("description", optional=True)
        choices = entity.get_attr("choice", data_type=list[Entity], optional=True)
        if choices:
            kwargs["choices"] = [choice.get_attr("value") for choice in choices]
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        context.declare(self.name)
        if self.name not in context.launch_configurations:
            if self.default_value is None:
                raise self.error(f"argument {self.name!r} is required: pass {self.name}:=<value>")
            context.launch_configurations[self.name] = perform(self.default_value, context)
        value = context.launch_configurations[self.name]
        if self.choices is not None and value not in self.choices:
            raise self.error(f"argument {self.name!r} is {value!r}; choose one of {self.choices}")


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


@expose_action("let")
class SetLaunchConfiguration(NameValueAction):
    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations[perform(self.name, context)] = perform(self.value, context)


class UnsetLaunchConfiguration(Action):
    def __init__(self, name: SomeSubstitutionsType, **kw: Any) -> None:
        super().__init__(**kw)
        self.name = name

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations.pop(perform(self.name, context), None)


@expose_action("reset")
class ResetLaunchConfigurations(Action):
    """Forget every launch configuration but the ones given (`<reset>` with `<keep>`s); the
    kept values are performed before anything is forgotten, as in ros2/launch."""

    def __init__(self, launch_configurations: dict | None = None, **kw: Any) -> None:
        super().__init__(**kw)
        self.launch_configurations = dict(launch_configurations or {})

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        keep = entity.get_attr("keep", data_type=list[Entity], optional=True) or []
        kwargs["launch_configurations"] = {
            tuple(parser.parse_substitution(item.get_attr("name"))): parser.parse_substitution(
                item.get_attr("value")
            )
            for item in keep
        }
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        kept = {
            perform(name, context): perform(value, context)
            for name, value in self.launch_configurations.items()
        }
        context.launch_configurations.clear()
        context.launch_configurations.update(kept)


def env_name(action: Any, context: LaunchContext) -> str:
    """The variable an environment action names, refused where no environment can hold it."""
    name = perform(action.name, context)
    if not name or "=" in name or "\0" in name:
        raise action.error(f"invalid environment variable name {name!r}")
    return name


@expose_action("set_env")
class SetEnvironmentVariable(NameValueAction):
    def execute(self, context: LaunchContext) -> None:
        context.set_env(env_name(self, context), perform(self.value, context))


@expose_action("unset_env")
class UnsetEnvironmentVariable(Action):
    def __init__(self, name: SomeSubstitutionsType, **kw: Any) -> None:
        super().__init__(**kw)
        self.name = name

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["name"] = parser.parse_substitution(entity.get_attr("name"))
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        context.set_env(env_name(self, context), None)


@expose_action("append_env")
class AppendEnvironmentVariable(Action):
    def __init__(
        self,
        name: SomeSubstitutionsType,
        value: SomeSubstitutionsType,
        prepend: bool | SomeSubstitutionsType = False,
        separator: SomeSubstitutionsType = os.pathsep,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.name, self.value, self.prepend, self.separator = name, value, prepend, separator

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["name"] = parser.parse_substitution(entity.get_attr("name"))
        kwargs["value"] = parser.parse_substitution(entity.get_attr("value"))
        prepend = entity.get_attr("prepend", optional=True)
        if prepend is not None:  # launch_xml's own test writes "yes"
            word = prepend.strip().lower()
            kwargs["prepend"] = {"yes": "true", "no": "false"}.get(word, prepend)
        separator = entity.get_attr("separator", optional=True)
        if separator is not None:
            kwargs["separator"] = parser.parse_substitution(separator)
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        name, value = env_name(self, context), perform(self.value, context)
        old = context.environment.get(name, "")
        separator = perform(self.separator, context)
        if old:
            value = (
                value + separator + old if flag(self.prepend, context) else old + separator + value
            )
        context.set_env(name, value)


@expose_action("log")
class LogInfo(Action):
    """A message on the launcher's screen, when the launch reaches it."""

    def __init__(self, *, msg: SomeSubstitutionsType, **kw: Any) -> None:
        super().__init__(**kw)
        self.msg = msg

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["msg"] = parser.parse_substitution(entity.get_attr("message"))
        entity.get_attr("level", optional=True)  # every message is said at INFO here
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        parts = normalize(self.msg, self.where)
        plain = all(isinstance(p, str) for p in parts)
        if context.locals.get("runtime") and (not plain or "once" in context.locals):
            # In an event handler: performed when the event happens, as ros2 launch does
            # (the event's values, an environment variable that is set by then).
            context.sink.add_step(lazy_step(self, context, lambda: perform(self.msg, context)))
            return
        text = perform(self.msg, context)
        context.sink.add_step(Step(context.when, "log", text, where=self.where))

    def step_when_returned(self, when: When, context: LaunchContext) -> Step:
        text = "".join(
            part if isinstance(part, str) else part.perform(context)
            for part in normalize(self.msg, self.where)
        )
        return Step(when, "log", text)


def lazy_step(
    action: Action, context: LaunchContext, text: Callable[[], str], kind: str = "log"
) -> Step:
    """A step of an event handler whose text is performed when the event happens, with the
    event in ``context.locals``; a substitution that fails then shuts the launch down with
    its one line, as it would end ros2 launch."""

    def call(info: dict) -> list[Step]:
        from launch.event_handlers import first_event
        from launch.events import event_from

        if not first_event(context, info):
            return []
        context.locals["event"] = event_from(info)
        try:
            return [Step(context.when, kind, text(), where=action.where)]
        except LaunchError as error:
            return [Step(context.when, "shutdown", str(error), where=action.where)]

    return Step(context.when, "call", kind, call=call, where=action.where)


class EmitEvent(Action):
    """Only the Shutdown event is emitted by launch files here."""

    def __init__(self, *, event: Any, **kw: Any) -> None:
        super().__init__(**kw)
        self.event = event

    def execute(self, context: LaunchContext) -> None:
        if not isinstance(self.event, ShutdownEvent):
            raise self.error(
                f"EmitEvent({type(self.event).__name__}) is not supported here; only "
                "EmitEvent(event=Shutdown(...))"
            )
        plain = isinstance(self.event.reason, str)
        if context.locals.get("runtime") and (not plain or "once" in context.locals):
            reason = lambda: perform(self.event.reason, context)  # noqa: E731
            context.sink.add_step(lazy_step(self, context, reason, "shutdown"))
            return
        reason = perform(self.event.reason, context)
        context.sink.add_step(Step(context.when, "shutdown", reason, where=self.where))

    def step_when_returned(self, when: When, context: LaunchContext) -> Step:
        return Step(when, "shutdown", str(getattr(self.event, "reason", "")))


class Shutdown(EmitEvent):
    """launch.actions.Shutdown: EmitEvent(event=Shutdown(reason=...))."""

    def __init__(self, *, reason: str = "reason not given", **kw: Any) -> None:
        super().__init__(event=ShutdownEvent(reason=reason), **kw)


class OpaqueFunction(Action):
    """A function of the launch file, called with the launch context; it may return actions."""

    def __init__(
        self,
        *,
        function: Callable[..., Any],
        args: Iterable[Any] | None = None,
        kwargs: dict[str, Any] | None = None,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.function, self.args, self.kwargs = function, list(args or []), dict(kwargs or {})

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        return self.function(context, *self.args, **self.kwargs)


@expose_action("group")
class GroupAction(Action):
    """Actions in a scope of their own (launch configurations, environment, remaps...)."""

    def __init__(
        self,
        actions: Iterable[LaunchDescriptionEntity],
        *,
        scoped: bool = True,
        forwarding: bool = True,
        launch_configurations: dict[Any, Any] | None = None,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.actions = list(actions)
        self.scoped, self.forwarding = scoped, forwarding
        self.launch_configurations = launch_configurations or {}

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        for name in ("scoped", "forwarding"):
            value = entity.get_attr(name, data_type=bool, optional=True)
            if value is not None:
                kwargs[name] = parser.parse_if_substitutions(value)
        keep = entity.get_attr("keep", data_type=list[Entity], optional=True) or []
        kwargs["launch_configurations"] = {  # a name's substitutions as a key: a tuple
            tuple(parser.parse_substitution(item.get_attr("name"))): parser.parse_substitution(
                item.get_attr("value")
            )
            for item in keep
        }
        kwargs["actions"] = [
            parser.parse_action(child) for child in entity.children if child.type_name != "keep"
        ]
        return cls, kwargs

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.actions

    def execute(self, context: LaunchContext) -> None:
        inner = context
        if flag(self.scoped, context):
            inner = context.child(forwarding=flag(self.forwarding, context))
        for name, value in self.launch_configurations.items():
            inner.launch_configurations[perform(name, context)] = perform(value, context)
        for action in self.actions:
            inner.visit(action)


@expose_action("timer")
class TimerAction(Action):
    """Its actions happen ``period`` seconds later."""

    def __init__(
        self,
        *,
        period: float | SomeSubstitutionsType,
        actions: Iterable[LaunchDescriptionEntity],
        cancel_on_shutdown: bool = True,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.period = period
        self.actions = list(actions)
        self.cancel_on_shutdown = cancel_on_shutdown

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        period = entity.get_attr("period", data_type=float, can_be_str=True)
        kwargs["period"] = parser.parse_if_substitutions(period)
        kwargs["actions"] = [parser.parse_action(child) for child in entity.children]
        return cls, kwargs

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.actions

    def execute(self, context: LaunchContext) -> None:
        period = seconds(self.period, context, self.where, "TimerAction period")
        if not flag(self.cancel_on_shutdown, context):
            context.sink.warn(
                f"{self.where}: TimerAction(cancel_on_shutdown=False): a shutdown cancels "
                "every timer in this launcher, this one too"
            )
        later = context.child(when=context.when.later(period))
        for action in self.actions:
            later.visit(action)


class RegisterEventHandler(Action):
    def __init__(self, event_handler: EventHandler, **kw: Any) -> None:
        super().__init__(**kw)
        self.event_handler = event_handler

    def execute(self, context: LaunchContext) -> None:
        register = getattr(self.event_handler, "register", None)
        if register is None:
            raise self.error(f"{type(self.event_handler).__name__} is not an event handler")
        register(context)


@expose_action("executable")
class ExecuteProcess(Action):
    """A process: ``cmd`` is a list of words (each text or substitutions); with ``shell``
    they are joined into one shell command line."""

    def __init__(
        self,
        *,
        cmd: Iterable[SomeSubstitutionsType],
        name: SomeSubstitutionsType | None = None,
        cwd: SomeSubstitutionsType | None = None,
        env: dict[Any, Any] | None = None,
        additional_env: dict[Any, Any] | None = None,
        shell: bool = False,
        sigterm_timeout: SomeSubstitutionsType | float | None = None,
        sigkill_timeout: SomeSubstitutionsType | float | None = None,
        emulate_tty: bool = False,
        prefix: SomeSubstitutionsType | None = None,
        output: SomeSubstitutionsType = "log",
        output_format: str = DEFAULT_OUTPUT_FORMAT,
        log_cmd: bool = False,
        on_exit: Any = None,
        respawn: bool | SomeSubstitutionsType = False,
        respawn_delay: float | None = None,
        respawn_max_retries: int | None = None,
        condition: Condition | None = None,
        **kw: Any,
    ) -> None:
        super().__init__(condition=condition, **kw)
        self.emulate_tty, self.log_cmd, self.output_format = emulate_tty, log_cmd, output_format
        self.cmd = list(cmd) if not isinstance(cmd, (str, Substitution)) else [cmd]
        self.name, self.cwd, self.env, self.additional_env = name, cwd, env, additional_env
        self.shell, self.prefix, self.output = shell, prefix, output
        self.sigterm_timeout, self.sigkill_timeout = sigterm_timeout, sigkill_timeout
        self.on_exit, self.respawn = on_exit, respawn
        self.respawn_delay, self.respawn_max_retries = respawn_delay, respawn_max_retries

    @classmethod
    def parse(
        cls, entity: Any, parser: Any, ignore: Iterable[str] = ()
    ) -> tuple[type, dict[str, Any]]:
        """<executable> (with ``ignore=("cmd",)``: what launch_ros's <node> shares with it).
        Each attribute is performed when the process is planned and checked at its tag's
        line; <env> children are its additional_env."""
        from launch.frontend.frontend_text import FrontendText, FrontendWords, split_words

        _, kwargs = super().parse(entity, parser)
        if "cmd" not in ignore:  # a <node> reads its name and args itself
            cmd = frontend_attr(entity, "cmd", _non_empty_cmd, FrontendWords)
            if cmd is None:
                raise entity.element.error("<executable> needs a non-empty 'cmd'")
            args = frontend_attr(entity, "args", split_words("args"), FrontendWords)
            kwargs["cmd"] = [cmd] + ([args] if args is not None else [])
            name = frontend_attr(entity, "name")
            if name is not None:
                kwargs["name"] = name
        checks: dict[str, Callable[[str, Any], str] | None] = {
            "cwd": None, "output": _output_check, "respawn": _flag_check("respawn"),
            "respawn_delay": number_check("respawn_delay"),
            "respawn_max_retries": number_check("respawn_max_retries", int),
            "sigterm_timeout": number_check("sigterm_timeout"),
            "sigkill_timeout": number_check("sigkill_timeout"),
        }  # fmt: skip
        for attr, check in checks.items():
            value = frontend_attr(entity, attr, check)
            if value is not None:
                kwargs[attr] = value
        prefix = frontend_attr(entity, "launch_prefix", split_words("launch_prefix"),
                               FrontendWords)  # fmt: skip
        if prefix is not None:
            kwargs["prefix"] = prefix
        on_exit = entity.get_attr("on_exit", optional=True)  # as ros2 launch: the word itself
        if on_exit not in (None, "", "shutdown"):
            raise entity.element.error(f"on_exit={on_exit!r} is not supported; use 'shutdown'")
        if on_exit == "shutdown":
            kwargs["on_exit"] = Shutdown()
        env = entity.get_attr("env", data_type=list[Entity], optional=True) or []
        if env:
            kwargs["additional_env"] = {
                FrontendText(item.get_attr("name"), item.element, _env_name_check): FrontendText(
                    item.get_attr("value"), item.element
                )
                for item in env
            }
        return cls, kwargs

    def process_decl(self, context: LaunchContext) -> NodeDecl:
        """The process as the launcher's plan holds it (launch_ros's Node fills in more)."""
        words = command_words(self.cmd, context)
        if not words or not words[0]:
            raise self.error("ExecuteProcess needs a non-empty cmd")
        label = (perform(self.name, context) or None) if self.name is not None else None
        if self.shell:
            first = shlex.split(words[0])[:1] if words[0].strip() else []
            label = label or (Path(first[0]).name if first else "sh")
            command = ["/bin/sh", "-c", " ".join(words)]
        else:
            command = words
        decl = NodeDecl(self.where, cmd=command, label=label, namespace="/")
        self.fill(decl, context)
        return decl

    def fill(self, decl: NodeDecl, context: LaunchContext) -> None:
        """What every process shares: environment, output, respawn, timeouts, prefix, cwd."""
        env = context.env_changes
        if self.env is not None:  # the whole environment: everything else unset
            given = {perform(k, context): perform(v, context) for k, v in self.env.items()}
            env = {name: None for name in os.environ if name not in given}
            env.update(given)
        for key, value in (self.additional_env or {}).items():
            if not enabled(key, context):
                continue  # a front-end's <env if=...>
            env[perform(key, context)] = perform(value, context)
        decl.env = env
        decl.output = perform(self.output, context) or "log"
        if decl.output not in ("screen", "log", "both"):
            raise self.error(f"output={decl.output!r}; use one of screen, log, both")
        decl.respawn = flag(self.respawn, context)
        delay = given_value(self.respawn_delay, context)
        if delay is not None:
            decl.respawn_delay = seconds(delay, context, self.where, "respawn_delay")
        # Not given: this launcher's default (it backs off and gives up); -1, as in ros2
        # launch, respawns for ever.
        retries = given_value(self.respawn_max_retries, context)
        decl.respawn_max_retries = DEFAULT_RESPAWN_MAX_RETRIES if retries is None else int(retries)
        for attr in ("sigterm_timeout", "sigkill_timeout"):
            value = given_value(getattr(self, attr), context)
            if value is not None:
                setattr(decl, attr, seconds(value, context, self.where, attr))
        if self.prefix is not None:
            decl.launch_prefix = shlex.split(perform(self.prefix, context))
        if self.cwd is not None:
            decl.cwd = perform(self.cwd, context) or None
        # emulate_tty (or the launch configuration of that name, as ros2 launch reads it):
        # the child's output is a pipe here, unbuffered either way; what a terminal adds is
        # rcutils' colours.
        tty = context.launch_configurations.get("emulate_tty", self.emulate_tty)
        if flag(tty, context) and "RCUTILS_COLORIZED_OUTPUT" not in context.environment:
            env["RCUTILS_COLORIZED_OUTPUT"] = "1"
        decl.when = context.when
        exit_actions = self.on_exit if isinstance(self.on_exit, list) else [self.on_exit]
        decl.required = any(isinstance(a, EmitEvent) and not callable(a) for a in exit_actions)

    def execute(self, context: LaunchContext) -> None:
        decl = self.process_decl(context)
        if self.output_format != DEFAULT_OUTPUT_FORMAT:
            decl.output_format = checked_output_format(self.output_format, self.where)
        if decl.required and decl.respawn:
            raise self.error("a process cannot both respawn and shut the launch down on exit")
        index = context.sink.add_node(decl)
        context.state.process_index[id(self)] = index
        if flag(self.log_cmd, context):  # ros2 launch's line, each time the process starts
            custom = self.env is not None or bool(self.additional_env)
            details = functools.partial(_process_details, custom)
            context.sink.add_step(
                Step(When("start", index), "call", call=details, where=self.where)
            )
        others = [a for a in normalize_actions(self.on_exit) if not isinstance(a, EmitEvent)]
        if others:  # on_exit=[...] besides Shutdown: an OnProcessExit handler of its own
            OnProcessExit(target_action=self, on_exit=others).register(context)


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


@expose_action("include")
class IncludeLaunchDescription(Action):
    """Another launch file, of any of the three formats, with arguments."""

    def __init__(
        self,
        launch_description_source: Any,
        *,
        launch_arguments: Iterable[tuple[Any, Any]] | None = None,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.launch_description_source = launch_description_source
        self.launch_arguments = list(launch_arguments or [])
        # Where a front-end wrote each argument (<arg> lines): the launcher then checks them
        # against the included file's declarations and names those lines in its warnings.
        self.arguments_at: dict[str, str] | None = None

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        from launch.launch_description_sources import AnyLaunchDescriptionSource

        _, kwargs = super().parse(entity, parser)
        source = parser.parse_substitution(entity.get_attr("file"))
        kwargs["launch_description_source"] = AnyLaunchDescriptionSource(source)
        arguments = entity.get_attr("arg", data_type=list[Entity], optional=True) or []
        kwargs["launch_arguments"] = [
            (item.get_attr("name"), parser.parse_substitution(item.get_attr("value")))
            + ((condition,) if (condition := parser.parse_condition(item)) else ())
            for item in arguments
        ]
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        source = self.launch_description_source
        location = getattr(source, "location", source)
        path = Path(perform(location, context))
        if not path.is_absolute():
            path = context.launch_file.parent / path
        if not path.is_file():
            raise self.error(f"included launch file {path} does not exist")
        # Every given argument becomes a launch configuration of the included file, declared
        # there or not; the included file sees the includer's configurations too, and what it
        # sets stays set after it (ros2 launch does not scope includes; the sink does this).
        given = {}
        for name, value, *condition in self.launch_arguments:
            # a front-end's <arg if=...> inside <include> is a third item: given only if it holds
            if not condition or condition[0].evaluate(context):
                given[perform(name, context)] = perform(value, context)
        try:
            context.include(path, given, self.where, self.arguments_at)
        except RecursionError:
            raise self.error("launch files include each other too deeply") from None


_ = (normalize, Substitution)
__getattr__ = module_getattr("launch.actions", lambda: __all__)
