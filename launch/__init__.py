"""launch: ros2/launch's Python API, as launch files use it, written for this project's
launcher (the launch system is not on PyPI). ``ros2 launch FILE.launch.py`` runs a file that
imports it; see launcher/python_files.py."""

from launch import (
    actions,
    conditions,
    descriptions,
    event_handlers,
    events,
    frontend,
    launch_description_sources,
    logging,
    substitutions,
)
from launch._base import (
    Action,
    Condition,
    EventHandler,
    LaunchDescriptionEntity,
    SomeSubstitutionsType,
    Substitution,
)
from launch._missing import module_getattr
from launch.event import Event
from launch.invalid_launch_file_error import InvalidLaunchFileError
from launch.launch_context import LaunchContext
from launch.launch_description import LaunchDescription
from launch.launch_description_sources import LaunchDescriptionSource
from launch.launch_service import LaunchService
from launch.some_entities_type import SomeEntitiesType, SomeEntitiesType_types_tuple
from launch.some_substitutions_type import SomeSubstitutionsType_types_tuple

__all__ = [
    "Action", "Condition", "Event", "EventHandler", "InvalidLaunchFileError", "LaunchContext",
    "LaunchDescription", "LaunchDescriptionEntity", "LaunchDescriptionSource", "LaunchService",
    "SomeEntitiesType", "SomeEntitiesType_types_tuple", "SomeSubstitutionsType",
    "SomeSubstitutionsType_types_tuple", "Substitution", "actions", "conditions",
    "descriptions", "event_handlers", "events", "frontend", "launch_description_sources",
    "logging", "substitutions",
]  # fmt: skip

__getattr__ = module_getattr("launch", lambda: __all__)
