"""launch_yaml.launch_description_sources.YAMLLaunchDescriptionSource."""

from launch.launch_description_sources import FrontendLaunchDescriptionSource


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    pass
