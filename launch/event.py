"""launch.event: Event, the base of every event (ros2/launch's launch/event.py)."""

from __future__ import annotations

from typing import Any


class Event:
    """An event; its attributes are what the launcher reports with it."""

    name = "launch.Event"

    def __init__(self, **fields: Any) -> None:
        self.__dict__.update(fields)
