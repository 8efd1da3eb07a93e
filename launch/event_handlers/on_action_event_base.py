"""launch.event_handlers.on_action_event_base: what the event handlers share: one event of one
process (or of any), its actions or function made into steps and processes of the plan that
wait for the event (``launch_foundation.declarations.When``)."""

from __future__ import annotations

import inspect
from typing import Any

from launch._base import Action, EventHandler, LaunchDescriptionEntity, is_ours
from launch.events import event_from
from launch.launch_context import LaunchContext
from launch_foundation.declarations import Step, When


class _OnEvent(EventHandler):
    """One event of one process (or of any, without target_action)."""

    event = ""
    takes_context = True  # a handler function is called (event, context); OnProcessIO (event)

    def __init__(
        self, target_action: Any = None, actions: Any = None, handle_once: bool = False
    ) -> None:
        super().__init__()
        if target_action is not None and not isinstance(target_action, Action):
            raise TypeError(
                f"{type(self).__name__}: target_action must be an action, not "
                f"{type(target_action).__name__}"
            )
        if not _handles(actions):
            raise TypeError(
                f"{type(self).__name__}: its actions must be an action, a list of them or a "
                f"function, not {type(actions).__name__}"
            )
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


def _handles(actions: Any) -> bool:
    """What an event handler may do: nothing, a function, an entity or a list of entities."""
    if actions is None or callable(actions) or isinstance(actions, LaunchDescriptionEntity):
        return True
    return isinstance(actions, (list, tuple)) and all(
        isinstance(item, LaunchDescriptionEntity) or callable(item) for item in actions
    )


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
        return [Step(when, "error", f"{line}: the event handler raised "
                     f"{type(error).__name__}: {error}")]  # fmt: skip
    steps = []
    results = result if isinstance(result, (list, tuple)) else [result] if result else []
    for action in results:
        step = action.step_when_returned(when, context) if isinstance(action, Action) else None
        if step is not None:  # LogInfo, EmitEvent (launch/actions/)
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


OnActionEventBase = _OnEvent  # ros2/launch's name for it
