"""launch.actions.ExecuteProcess (``<executable>``): a process of the plan."""

from __future__ import annotations

import functools
import os
import shlex
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from launch._base import Action, Condition, SomeSubstitutionsType, Substitution, perform
from launch.actions._common import (
    DEFAULT_OUTPUT_FORMAT,
    _env_name_check,
    _flag_check,
    _non_empty_cmd,
    _output_check,
    _process_details,
    checked_output_format,
    command_words,
    enabled,
    flag,
    frontend_attr,
    given_value,
    normalize_actions,
    number_check,
    seconds,
)
from launch.actions.emit_event import EmitEvent
from launch.actions.shutdown_action import Shutdown
from launch.event_handlers import OnProcessExit
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext
from launch_foundation.declarations import (
    DEFAULT_RESPAWN_MAX_RETRIES,
    NodeDecl,
    Step,
    When,
)


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
        for attr in ("shell", "emulate_tty"):
            value = entity.get_attr(attr, data_type=bool, optional=True)
            if value is not None:
                kwargs[attr] = parser.parse_if_substitutions(value)
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

    def get_sub_entities(self) -> list[Any]:
        """The actions that happen when the process exits (on_exit)."""
        return normalize_actions(self.on_exit)

    def process_decl(self, context: LaunchContext) -> NodeDecl:
        """The process as the launcher's plan holds it (launch_ros's Node fills in more)."""
        words = command_words(self.cmd, context)
        if not words or not words[0]:
            raise self.error("ExecuteProcess needs a non-empty cmd")
        label = (perform(self.name, context) or None) if self.name is not None else None
        if flag(self.shell, context):
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
        decl.output = output_mode(self.output, context)
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


def output_mode(output: Any, context: LaunchContext) -> str:
    """ExecuteProcess's output: screen, log or both; as a dict of streams (``{"stdout":
    "screen", "stderr": "log"}``, as ros2 launch takes it) what its values add up to."""
    if not isinstance(output, dict):
        return perform(output, context) or "log"
    words = {perform(value, context) for value in output.values()}
    screen = bool(words & {"screen", "both"})
    log = bool(words & {"log", "both", "own_log"})
    return "both" if screen and log else "screen" if screen else "log"
