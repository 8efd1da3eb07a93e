"""launch.events.process: the events of a process, where ros2/launch has them
(``from launch.events.process import ProcessExited``); an event's attributes are what the
launcher reports with it (pid, returncode, text)."""

from __future__ import annotations

from launch.event import Event

__all__ = ["ProcessExited", "ProcessIO", "ProcessStarted", "ProcessStderr", "ProcessStdout"]


class _ProcessEvent(Event):
    """An event of one process."""


class ProcessStarted(_ProcessEvent):
    pass


class ProcessExited(_ProcessEvent):
    pass


class ProcessIO(_ProcessEvent):
    pass


class ProcessStdout(ProcessIO):
    pass


class ProcessStderr(ProcessIO):
    pass
