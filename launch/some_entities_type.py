"""launch.some_entities_type: what an entities argument may be."""

from collections.abc import Iterable

from launch._base import LaunchDescriptionEntity

SomeEntitiesType = LaunchDescriptionEntity | Iterable[LaunchDescriptionEntity]
SomeEntitiesType_types_tuple = (LaunchDescriptionEntity, list, tuple)

__all__ = ["SomeEntitiesType", "SomeEntitiesType_types_tuple"]
