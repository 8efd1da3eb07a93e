"""launch.event_handlers: actions that happen when a process starts, exits or prints a line,
or when the launch shuts down. Each becomes steps and processes of the plan that wait for
their event (``launch_foundation.declarations.When``)."""

from __future__ import annotations

import inspect
from typing import Any

from launch._base import Action, EventHandler, is_ours
from launch._missing import module_getattr
from launch.events import event_from
from launch.launch_context import LaunchContext
from launch_foundation.declarations import Step, When

__all__ = [
    "OnExecutionComplete", "OnProcessExit", "OnProcessIO", "OnProcessStart", "OnShutdown",
]  # fmt: skip


class _OnEvent(EventHandler):
    """One event of one process (or of any, without target_action)."""

    event = ""
    takes_context = True  # a handler function is called (event, context); OnProcessIO (event)

    def __init__(
        self, target_action: Any = None, actions: Any = None, handle_once: bool = False
    ) -> None:
        super().__init__()
        self.target_action = target_action
        self.actions = actions
        self.handle_once = handle_once  # only the first such event (a respawning process)

    def register(self, context: LaunchContext) -> None:
        index = None
        if self.target_action is not None:
            index = context.state.process_index.get(id(self.target_action))
            if index is None:  # its target is executed later: register it then
                context.state.deferred_handlers.append((self, context))
                return
        self.register_at(context, When(self.event, index))

    def register_at(self, context: LaunchContext, when: When) -> None:
        inner = context.child(when=when)
        inner.locals = {"runtime": True}
        if self.handle_once:  # the steps made below happen for the first event only
            inner.locals["once"] = {}
        if self.actions is None:
            return
        if callable(self.actions) and not isinstance(self.actions, Action):
            function = self.actions

            def call(info: dict) -> list[Step]:
                if not first_event(inner, info):
                    return []
                return run_handler_function(function, info, inner, self, when)

            context.sink.add_step(Step(when, "call", call=call, where=self.where))
            return
        actions = self.actions if isinstance(self.actions, (list, tuple)) else [self.actions]
        for action in actions:
            inner.visit(action)


def first_event(context: LaunchContext, info: dict) -> bool:
    """False for a handle_once handler's steps at any event after its first (the supervisor
    hands every step of one event the same ``info``)."""
    once = context.locals.get("once")
    return once is None or once.setdefault("info", info) is info


def run_handler_function(
    function: Any, info: dict, context: LaunchContext, handler: _OnEvent, when: When
) -> list[Step]:
    """Call an event handler's function of the launch file with the event, when it happens;
    what it returns must be LogInfo or EmitEvent(Shutdown): the plan's processes are fixed."""
    event = event_from(info)
    context.locals["event"] = event
    try:
        takes = len(inspect.signature(function).parameters)
        result = (
            function(event, context) if takes >= 2 and handler.takes_context else function(event)
        )
    except Exception as error:  # the launch file's code: its own line, then shut down
        line = _user_line(error) or handler.where
        return [Step(when, "shutdown", f"{line}: the event handler raised "
                     f"{type(error).__name__}: {error}")]  # fmt: skip
    steps = []
    results = result if isinstance(result, (list, tuple)) else [result] if result else []
    for action in results:
        step = action.step_when_returned(when, context) if isinstance(action, Action) else None
        if step is not None:  # LogInfo, EmitEvent (launch/actions.py)
            steps.append(step)
        else:
            steps.append(Step(when, "log", f"{handler.where}: an event handler's function "
                              f"returned {type(action).__name__}; only LogInfo and "
                              "EmitEvent(Shutdown) can happen from a function here"))  # fmt: skip
    return steps


def _user_line(error: BaseException) -> str | None:
    frames = [f for f in _frames(error.__traceback__) if not is_ours(f.filename)]
    return f"{frames[-1].filename}:{frames[-1].lineno}" if frames else None


def _frames(tb: Any) -> list[Any]:
    import traceback

    return list(traceback.extract_tb(tb))


class OnProcessStart(_OnEvent):
    event = "start"

    def __init__(
        self, *, target_action: Any = None, on_start: Any, handle_once: bool = False
    ) -> None:
        super().__init__(target_action, on_start, handle_once)


class OnProcessExit(_OnEvent):
    event = "exit"

    def __init__(
        self, *, target_action: Any = None, on_exit: Any, handle_once: bool = False
    ) -> None:
        super().__init__(target_action, on_exit, handle_once)


class OnExecutionComplete(_OnEvent):
    """For a process, its execution completes when it exits."""

    event = "exit"

    def __init__(
        self, *, target_action: Any = None, on_completion: Any, handle_once: bool = False
    ) -> None:
        super().__init__(target_action, on_completion, handle_once)


class OnProcessIO(_OnEvent):
    takes_context = False

    def __init__(
        self,
        *,
        target_action: Any = None,
        on_stdin: Any = None,
        on_stdout: Any = None,
        on_stderr: Any = None,
        handle_once: bool = False,
    ) -> None:
        super().__init__(target_action, None, handle_once)
        self.on_stdout, self.on_stderr = on_stdout, on_stderr

    def register_at(self, context: LaunchContext, when: When) -> None:
        for event, actions in (("stdout", self.on_stdout), ("stderr", self.on_stderr)):
            if actions is not None:
                self.actions = actions
                super().register_at(context, When(event, when.target))


class OnShutdown(_OnEvent):
    event = "shutdown"

    def __init__(self, *, on_shutdown: Any, handle_once: bool = False) -> None:
        super().__init__(None, on_shutdown, handle_once)


__getattr__ = module_getattr("launch.event_handlers", lambda: __all__)
