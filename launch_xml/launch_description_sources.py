"""launch_xml.launch_description_sources.XMLLaunchDescriptionSource."""

from launch.launch_description_sources import FrontendLaunchDescriptionSource


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    pass
