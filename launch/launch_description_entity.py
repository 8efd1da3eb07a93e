"""launch.launch_description_entity: LaunchDescriptionEntity."""

from launch._base import LaunchDescriptionEntity

__all__ = ["LaunchDescriptionEntity"]
