"""launch_xml.launch_description_sources.XMLLaunchDescriptionSource."""

from launch.launch_description_sources import LaunchDescriptionSource


class XMLLaunchDescriptionSource(LaunchDescriptionSource):
    pass
