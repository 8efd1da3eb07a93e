"""launch.launch_service.LaunchService: run LaunchDescriptions from a script, as
launch_testing and users' tools do (``ls = LaunchService(); ls.include_launch_description(ld);
ls.run()``).

The descriptions are executed by the model's own executor (``LaunchContext.visit``) into a
plan, and the plan is run by the tool that supervises processes: this project's launcher,
found through the ``launch.runner`` entry point (``launcher.service.run``), as ros2/launch
finds its front-ends, so that ``launch`` imports nothing above it. Plan, then supervise: the
processes, event handlers and timers of the descriptions run as they do under ``ros2
launch``; an event emitted from another thread while it runs (``emit_event``) is not seen by
the plan (a deliberate difference, see docs/dev/launch-upstream-tests.md), ``shutdown()``
ends the run.
"""

from __future__ import annotations

import os
import signal
import threading
from typing import Any

from launch.launch_context import LaunchContext
from launch_foundation import LaunchError

RUNNER_GROUP = "launch.runner"  # the entry point of the tool that plans and supervises


def _runner() -> Any:
    """The installed tool's run(descriptions, configurations, argv, debug, started)."""
    from importlib.metadata import entry_points

    found = list(entry_points(group=RUNNER_GROUP))
    if not found:
        raise LaunchError(f"no launch runner is installed (entry point group {RUNNER_GROUP!r})")
    return found[0].load()


class LaunchService:
    """Collects descriptions (``include_launch_description``) and runs them (``run``)."""

    def __init__(
        self, *, argv: list[str] | None = None, noninteractive: bool = False, debug: bool = False
    ) -> None:
        self.__context = LaunchContext(argv=argv, noninteractive=noninteractive)
        self.__descriptions: list[Any] = []
        self.__events: list[Any] = []
        self.__debug = debug
        self.__running = threading.Event()
        self.__shutdown = threading.Event()
        self.__lock = threading.Lock()

    @property
    def context(self) -> LaunchContext:
        return self.__context

    @property
    def task(self) -> None:  # ros2/launch's asyncio task: this service runs without one
        return None

    def include_launch_description(self, launch_description: Any) -> None:
        """Add a LaunchDescription to run (before ``run``)."""
        from launch.launch_description import LaunchDescription

        if not isinstance(launch_description, LaunchDescription):
            raise LaunchError(
                f"include_launch_description() takes a LaunchDescription, not "
                f"{type(launch_description).__name__}"
            )
        with self.__lock:
            if self.__running.is_set():
                raise LaunchError("LaunchService: include descriptions before run()")
            self.__descriptions.append(launch_description)

    def emit_event(self, event: Any) -> None:
        """Keep an event (it reaches no running plan: see the module docstring)."""
        with self.__lock:
            self.__events.append(event)

    def shutdown(self, force_sync: bool = False) -> None:
        """End the run: its processes are stopped as on Ctrl-C."""
        self.__shutdown.set()
        if self.__running.is_set():
            os.kill(os.getpid(), signal.SIGINT)

    def _executed(self, context: LaunchContext) -> None:
        """The run's context once its descriptions executed: what they set, for the caller."""
        self.__context = context

    def run(self, *, shutdown_when_idle: bool = True) -> int:
        """Execute the descriptions into a plan and supervise it until it ends (every process
        exited, a Shutdown, Ctrl-C or ``shutdown()``). The exit code: 0, 1 after an error (one
        line on stderr), 130 after Ctrl-C."""
        import sys

        if self.__shutdown.is_set():
            return 0
        try:
            run = _runner()
        except LaunchError as error:
            print(f"error: {error}", file=sys.stderr)
            return 1
        try:
            return run(
                list(self.__descriptions),
                dict(self.__context.launch_configurations),
                self.__context.argv,
                self.__debug,
                self.__running.set,
                self._executed,
            )
        finally:
            self.__running.clear()
