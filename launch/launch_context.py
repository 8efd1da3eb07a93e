"""launch.launch_context.LaunchContext: what actions and substitutions see while the model's
executor runs a description (``LaunchContext.visit``), and the scope it holds outside a
launch."""

from __future__ import annotations

import os
import sys
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from launch._base import Action, EventHandler, LaunchDescriptionEntity, Substitution, caller_where
from launch_foundation.declarations import AT_START, NodeDecl, PlanSink, Step, When
from launch_foundation.errors import LaunchError
from launch_foundation.parse import Element

if TYPE_CHECKING:  # the front-ends' scope, as their substitutions read it
    from launch_foundation.substitutions import Context as Scope


_DETACHED_ANON_NAMES: dict[str, str] = {}  # a name's anonymous name outside a launch


@dataclass
class _DetachedScope:
    """The values of a LaunchContext made outside a launch (the fields of launcher/scope.py's
    Scope that LaunchContext reads)."""

    args: dict[str, str] = field(default_factory=dict)
    env: dict[str, str | None] = field(default_factory=dict)
    namespace: str = "/"
    remaps: list[tuple[str, str]] = field(default_factory=list)
    params: list[tuple[str, Any]] = field(default_factory=list)
    params_files: list[str] = field(default_factory=list)
    declared: dict[str, int] = field(default_factory=dict)
    file: Path = field(default_factory=lambda: Path("<launch>"))
    when: When = AT_START
    fmt: str = "ros2"

    def child(self, **changes: Any) -> _DetachedScope:
        copies = {"args": dict(self.args), "env": dict(self.env), "remaps": list(self.remaps),
                  "params": list(self.params), "params_files": list(self.params_files)}  # fmt: skip
        return replace(self, **{**copies, **changes})

    def anon(self, name: str) -> str:
        """name_host_pid_number, as ros2 launch makes an anonymous name; the same each time."""
        made = _DETACHED_ANON_NAMES
        if name not in made:
            import random
            import socket

            host = "".join(c if c.isalnum() else "_" for c in socket.gethostname())
            made[name] = f"{name}_{host}_{os.getpid()}_{random.randrange(10**9)}"
        return made[name]

    # What a front-end's substitutions read of their context
    # (launch_foundation.substitutions.Context).
    allow_code = True  # made by Python code: its own $(command) and $(eval) are its own code

    def read_arg(self, name: str, element: Element) -> str:
        if name not in self.args:
            raise element.error(f"launch configuration {name!r} is not set")
        return self.args[name]

    def charge(self, size: int, element: Element) -> None:
        """Outside a launch there is no whole launch to count toward."""


class _NoPlan:
    """The sink of a LaunchContext made outside a launch: nothing can be added to a plan."""

    def add_node(self, node: NodeDecl) -> int:
        raise LaunchError(f"{node.where}: this LaunchContext is not part of a launch")

    def add_step(self, step: Step) -> None:
        raise LaunchError(f"{step.where}: this LaunchContext is not part of a launch")

    def warn(self, text: str) -> None:
        print(f"[WARNING] [launch]: {text}", file=sys.stderr)

    def include(self, path: Path, given: dict[str, str], scope: Any, *where: Any) -> None:
        raise LaunchError(f"{path}: this LaunchContext is not part of a launch")


class _Environment(dict):
    """LaunchContext.environment: ``os.environ`` with a scope's changes (``changes``: name ->
    value, None for unset) applied; writes and deletes go to ``changes``."""

    def __init__(self, changes: dict[str, str | None]) -> None:
        merged = dict(os.environ)
        for name, value in changes.items():
            if value is None:
                merged.pop(name, None)
            else:
                merged[name] = value
        super().__init__(merged)
        self._changes = changes

    def __setitem__(self, name: str, value: str) -> None:
        super().__setitem__(name, value)
        self._changes[name] = value

    def __delitem__(self, name: str) -> None:
        super().__delitem__(name)
        self._changes[name] = None

    def pop(self, name: str, *default: Any) -> Any:
        if name in self:
            self._changes[name] = None
        return super().pop(name, *default)

    def update(self, *args: Any, **kwargs: Any) -> None:
        for name, value in dict(*args, **kwargs).items():
            self[name] = value

    def clear(self) -> None:
        for name in list(self):
            del self[name]

    def setdefault(self, name: str, default: Any = None) -> Any:
        if name not in self:
            self[name] = default
        return self[name]


class _Locals(dict):
    """LaunchContext.locals: a dict whose keys read as attributes too (``context.locals.event``)."""

    def __getattr__(self, name: str) -> Any:
        try:
            return self[name]
        except KeyError:
            raise AttributeError(f"context.locals has no {name!r}") from None


class LaunchState:
    """What one launch's executor keeps across files: the index of each process action (what
    an event handler's target_action names), the handlers waiting for their target, the
    launch configurations read (an argument read but not declared is not a typo), and the
    actions executed (kept alive: their id() names them)."""

    def __init__(self) -> None:
        self.executed: dict[int, Any] = {}
        self.process_index: dict[int, int] = {}
        self.deferred_handlers: list[tuple[Any, LaunchContext]] = []
        self.configurations_read: set[str] = set()


class LaunchContext:
    """What actions and substitutions see, as ros2/launch's LaunchContext: the launch
    configurations, the environment, launch_ros's namespace, remaps and parameters for the
    nodes that follow, and in an event handler the event (``locals``). Executing an entity
    hands its result to ``sink`` (launch_foundation.declarations.PlanSink), the one interface to the
    launcher. ``scope`` holds the values (the front-ends' scope, launcher/scope.py): only
    this class reads it, through the properties below."""

    def __init__(
        self,
        scope: Scope | None = None,
        sink: PlanSink | None = None,
        state: LaunchState | None = None,
        locals_: dict[str, Any] | None = None,
        *,
        argv: list[str] | None = None,
        noninteractive: bool = False,
    ) -> None:
        # Without a scope (``LaunchContext()`` in OpaqueFunction code or a test, as ros2/launch
        # allows): launch configurations and the rest of its own, and no plan to add to.
        self._scope: Any = scope if scope is not None else _DetachedScope()
        self.sink: PlanSink = sink if sink is not None else _NoPlan()
        self.state = state if state is not None else LaunchState()
        self.locals = _Locals(locals_ or {})
        self._argv, self._noninteractive = list(argv or []), noninteractive
        self._stacks: dict[str, list[dict[str, Any]]] = {}

    @property
    def launch_configurations(self) -> dict[str, str]:
        return self._scope.args

    @property
    def environment(self) -> _Environment:
        """The environment of the processes that follow, as a mutable mapping: the launcher's
        own environment with what this scope set (SetEnvironmentVariable, ``<set_env>``) and
        unset. Writing to it changes the scope, never the launcher's own ``os.environ``."""
        return _Environment(self._scope.env)

    @property
    def allow_code(self) -> bool:
        """Whether a front-end's ``$(command)`` and code in ``$(eval)`` may run (the user's
        --allow-code; a context made by Python code itself: yes)."""
        return bool(getattr(self._scope, "allow_code", False))

    @property
    def current_launch_file_path(self) -> str | None:
        """The launch file being read (ThisLaunchFile), None outside one."""
        given = self.locals.get("current_launch_file_path")  # set by who loads a file
        if given is not None:
            return str(given)
        file = getattr(self._scope, "file", None)
        return None if file is None or str(file) == "<launch>" else str(file)

    @property
    def argv(self) -> list[str]:
        return list(self._argv)

    @property
    def noninteractive(self) -> bool:
        return self._noninteractive

    @property
    def is_shutdown(self) -> bool:
        return bool(self.state.__dict__.get("shutdown", False))

    def _push_launch_configurations(self) -> None:
        self._stacks.setdefault("configurations", []).append(dict(self._scope.args))

    def _pop_launch_configurations(self) -> None:
        saved = self._stacks.get("configurations")
        if not saved:
            raise RuntimeError("launch_configurations stack unexpectedly empty")
        self._scope.args.clear()
        self._scope.args.update(saved.pop())

    def _push_environment(self) -> None:
        self._stacks.setdefault("environment", []).append(dict(self._scope.env))

    def _pop_environment(self) -> None:
        saved = self._stacks.get("environment")
        if not saved:
            raise RuntimeError("environment stack unexpectedly empty")
        self._scope.env.clear()
        self._scope.env.update(saved.pop())

    def _reset_environment(self) -> None:
        """Back to the launcher's own environment (ResetEnvironment)."""
        self._scope.env.clear()

    def set_env(self, name: str, value: str | None) -> None:
        """Set (None: unset) a variable for the processes that follow in this scope."""
        self._scope.env[name] = value

    @property
    def env_changes(self) -> dict[str, str | None]:
        """The variables set (None: unset) for the processes that follow."""
        return dict(self._scope.env)

    @property
    def ros_namespace(self) -> str:
        return self._scope.namespace

    @ros_namespace.setter
    def ros_namespace(self, value: str) -> None:
        self._scope.namespace = value

    @property
    def ros_remaps(self) -> list[tuple[str, str]]:
        """launch_ros's global remaps (SetRemap), for the nodes that follow; add to it."""
        return self._scope.remaps

    @property
    def ros_params(self) -> list[tuple[str, Any]]:
        """launch_ros's global parameters (SetParameter), for the nodes that follow."""
        return self._scope.params

    @property
    def ros_params_files(self) -> list[str]:
        """launch_ros's global parameters files (SetParametersFromFile)."""
        return self._scope.params_files

    @property
    def launch_file(self) -> Path:
        """The launch file being executed (ThisLaunchFile)."""
        return self._scope.file

    @property
    def when(self) -> When:
        """When what executes here happens: at the start, after a timer, at an event."""
        return self._scope.when

    @property
    def frontend_scope(self) -> Scope:
        """The front-ends' substitution context ($(...) in a parameters file, allow_substs)."""
        return self._scope

    def declare(self, name: str) -> None:
        """A launch argument is declared here (named in errors about undeclared ones)."""
        self._scope.declared[name] = 0

    def anon(self, name: str) -> str:
        return self._scope.anon(name)

    def include(
        self,
        path: Path,
        given: dict[str, str],
        where: str | None = None,
        given_at: dict[str, str] | None = None,
    ) -> None:
        """Read another launch file with ``given`` arguments (not scoped, as ros2 launch),
        included at file:line ``where``, each argument written at ``given_at[name]``."""
        self.sink.include(path, given, self._scope, where, given_at)

    def register_event_handler(self, event_handler: EventHandler, append: bool = False) -> None:
        """Keep a handler (ros2/launch's context holds them; the plan's handlers are steps)."""
        handlers = self._stacks.setdefault("handlers", [])  # type: ignore[arg-type]
        handlers.append(event_handler) if append else handlers.insert(0, event_handler)

    def unregister_event_handler(self, event_handler: EventHandler) -> None:
        handlers = self._stacks.get("handlers", [])
        if event_handler not in handlers:
            raise ValueError(f"{type(event_handler).__name__} is not registered")
        handlers.remove(event_handler)

    @property
    def _event_handlers(self) -> list[Any]:
        return list(self._stacks.get("handlers", []))

    def perform_substitution(self, substitution: Substitution) -> str:
        return substitution.perform(self)

    def extend_locals(self, values: dict[str, Any]) -> None:
        self.locals.update(values)

    def extend_globals(self, values: dict[str, Any]) -> None:
        self.state.__dict__.setdefault("globals", {}).update(values)
        for name, value in values.items():
            self.locals.setdefault(name, value)

    def get_locals_as_dict(self) -> dict[str, Any]:
        return dict(self.locals)

    def child(self, *, forwarding: bool = True, when: When | None = None) -> LaunchContext:
        """A scope of its own (GroupAction, a timer, an event handler): what is set inside
        does not leak out. Without ``forwarding`` it starts with no launch configurations;
        ``when``: its actions happen then."""
        changes: dict[str, Any] = {} if forwarding else {"args": {}}
        if when is not None:
            changes["when"] = when
        return LaunchContext(self._scope.child(**changes), self.sink, self.state, self.locals)

    def visit(self, entity: Any) -> None:
        """Execute one entity of a description, or refuse what is not one."""
        if isinstance(entity, Action):
            for sub in entity.visit(self) or []:
                self.visit(sub)
        elif isinstance(entity, LaunchDescriptionEntity):
            for sub in entity.execute(self) or []:
                self.visit(sub)
        elif entity is not None:
            raise LaunchError(
                f"{caller_where()}: {type(entity).__name__} is not a launch action "
                "(a LaunchDescription holds actions: Node, ExecuteProcess, ...)"
            )
