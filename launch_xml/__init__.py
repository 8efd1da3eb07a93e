"""launch_xml: the launch XML front-end (its Entity and Parser for launch.frontend) and its
XMLLaunchDescriptionSource, for Python launch files that include XML."""

from launch_xml.entity import Entity
from launch_xml.parser import Parser

__all__ = ["Entity", "Parser"]
