"""Python launch files (``*.launch.py``, ``*_launch.py``): the Python front-end.

The file is run (a Python launch file is code, as in ROS 2), its
``generate_launch_description()`` called, and the LaunchDescription it returns executed into
the same plan the XML and YAML front-ends build (the ``launch`` and ``launch_ros`` packages of
this project are the API it imports). An error in the file shows the file's own traceback
lines, never the launcher's.
"""

from __future__ import annotations

import types
from pathlib import Path
from typing import TYPE_CHECKING, Any

from launch_foundation.declarations import ArgInfo, When
from launch_foundation.errors import LaunchError
from ros_tutorials_common.bounded import InputError, read_text

if TYPE_CHECKING:  # the loader calls this module with its scope
    from launcher.scope import Scope


class LaunchFileRaised(LaunchError):
    """A Python launch file raised: ``traceback`` holds its own frames, to print first."""

    def __init__(self, message: str, traceback_text: str) -> None:
        super().__init__(message)
        self.traceback = traceback_text


def _user_traceback(error: BaseException) -> tuple[str, str]:
    """The traceback lines in the launch file (and its own modules), and its last file:line."""
    import traceback

    from launch._base import is_ours

    frames = [frame for frame in traceback.extract_tb(error.__traceback__)
              if not is_ours(frame.filename)]  # fmt: skip
    lines = ["Traceback (most recent call last):", *traceback.format_list(frames)]
    lines += traceback.format_exception_only(type(error), error)
    where = f"{frames[-1].filename}:{frames[-1].lineno}" if frames else ""
    return "".join(line if line.endswith("\n") else line + "\n" for line in lines), where


def _call(path: Path, function: Any, *args: Any) -> Any:
    """Run the launch file's code; what it raises becomes a LaunchError with its traceback."""
    try:
        return function(*args)
    except LaunchError:
        raise
    except SyntaxError as error:
        line = f":{error.lineno}" if error.lineno else ""
        raise LaunchError(f"{error.filename or path}{line}: SyntaxError: {error.msg}") from None
    except (Exception, RecursionError) as error:
        text, where = _user_traceback(error)
        where = where or str(path)
        raise LaunchFileRaised(
            f"{where}: the launch file raised {type(error).__name__}: {error}", text
        ) from None


def load_description(path: Path) -> Any:
    """Run the file and call its generate_launch_description(): the LaunchDescription."""
    from launch import LaunchDescription

    try:
        source = read_text(path)
    except InputError as error:
        raise LaunchError(f"launch file: {error}") from None
    module = types.ModuleType(f"launch_file_{abs(hash(str(path)))}")
    module.__file__ = str(path)
    code = _call(path, compile, source, str(path), "exec")
    _call(path, exec, code, module.__dict__)
    generate = module.__dict__.get("generate_launch_description")
    if not callable(generate):
        raise LaunchError(f"{path}: a Python launch file defines generate_launch_description()")
    description = _call(path, generate)
    if not isinstance(description, LaunchDescription):
        raise LaunchError(
            f"{path}: generate_launch_description() returned {type(description).__name__}, "
            "not a LaunchDescription"
        )
    return description


def resolve_python_file(path: Path, scope: Scope, strict: bool) -> None:
    """Execute a Python launch file into the launch plan of ``scope``'s loader
    (launcher/loading.py)."""
    from launch.launch_context import LaunchContext

    description = load_description(path)
    loader = scope.loader
    state = loader.launch_state()  # one executor state for the whole launch
    scope.args.update(scope.given)  # launch configurations: the given values first
    context = LaunchContext(scope, loader.plan, state)
    deferred_before = len(state.deferred_handlers)
    _call(path, context.visit, description)
    # Handlers whose target process was executed after them.
    waiting = state.deferred_handlers[deferred_before:]
    del state.deferred_handlers[deferred_before:]
    for handler, handler_context in waiting:
        index = state.process_index.get(id(handler.target_action))
        if index is None:
            loader.warn(
                f"{handler.where}: {type(handler).__name__}'s target_action is never run, "
                "so its actions never happen"
            )
            continue
        _call(path, handler.register_at, handler_context, When(handler.event, index))
    if strict:  # ros2 launch takes them all as configurations: only a typo is worth a line
        declared = {info.name for info in describe_python_args(path, description)}
        unknown = sorted(set(scope.given) - declared - state.configurations_read)
        if unknown:
            names = ", ".join(sorted(declared)) or "none"
            loader.warn(
                f"{path}: {path.name} declares no argument {', '.join(map(repr, unknown))} "
                f"and does not read it (declared: {names})"
            )


def describe_python_args(path: Path, description: Any = None) -> list[ArgInfo]:
    """The arguments a Python launch file declares, for --show-args (nothing is started)."""
    description = description or load_description(path)
    infos = []
    for action in description.get_launch_arguments():
        default = action.default_value
        if default is not None and not isinstance(default, str):
            default = _describe(default)
        infos.append(
            ArgInfo(
                action.name,
                default,
                action.description or "",
                [str(choice) for choice in action.choices or []],
                False,
                action.where,
            )
        )
    return infos


def _describe(value: Any) -> str:
    """A default made of substitutions, as ros2 launch --show-args shows it."""
    from launch._base import normalize

    parts = []
    for part in normalize(value):
        if isinstance(part, str):
            parts.append(part)
        elif hasattr(part, "text"):
            parts.append(part.text)
        elif hasattr(part, "variable_name"):
            parts.append(f"LaunchConfig('{part.variable_name}')")
        else:
            parts.append(part.describe())
    return "".join(parts)
