"""launch_ros: ROS nodes in Python launch files (Node, PushRosNamespace, SetParameter,
SetRemap, FindPackageShare...), written for this project's launcher like ``launch``."""

from launch._missing import module_getattr
from launch_ros import actions, parameter_descriptions, substitutions

__all__ = ["actions", "parameter_descriptions", "substitutions"]
__getattr__ = module_getattr("launch_ros", lambda: __all__)
