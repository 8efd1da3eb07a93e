"""launch_yaml.launch_description_sources.YAMLLaunchDescriptionSource."""

from launch.launch_description_sources import LaunchDescriptionSource


class YAMLLaunchDescriptionSource(LaunchDescriptionSource):
    pass
