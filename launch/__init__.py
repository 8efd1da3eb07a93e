"""launch: ros2/launch's Python API, as launch files use it, written for this project's
launcher (the launch system is not on PyPI). ``ros2 launch FILE.launch.py`` runs a file that
imports it; see launcher/python_files.py."""

from launch import (
    actions,
    conditions,
    event_handlers,
    events,
    launch_description_sources,
    substitutions,
)
from launch._base import (
    Action,
    Condition,
    EventHandler,
    LaunchContext,
    LaunchDescriptionEntity,
    SomeSubstitutionsType,
    Substitution,
)
from launch._missing import module_getattr
from launch.launch_description import LaunchDescription
from launch.launch_description_sources import LaunchDescriptionSource

__all__ = [
    "Action", "Condition", "EventHandler", "LaunchContext", "LaunchDescription",
    "LaunchDescriptionEntity", "LaunchDescriptionSource", "SomeSubstitutionsType",
    "Substitution", "actions", "conditions", "event_handlers", "events",
    "launch_description_sources", "substitutions",
]  # fmt: skip

__getattr__ = module_getattr("launch", lambda: __all__)
