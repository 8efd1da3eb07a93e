"""launch_yaml: the launch YAML front-end (its Entity and Parser for launch.frontend) and
its YAMLLaunchDescriptionSource, for Python launch files that include YAML."""

from launch_yaml.entity import Entity
from launch_yaml.parser import Parser

__all__ = ["Entity", "Parser"]
