"""launch_ros: ROS nodes in Python launch files (Node, PushRosNamespace, SetParameter,
SetRemap, FindPackageShare...), written for this project's launcher like ``launch``."""

# ruff: noqa: E402 - the imports follow the release of Ctrl-C, as in every package here

from ros_tutorials_common.ctrl_c import release as _release_ctrl_c

_release_ctrl_c()  # Ctrl-C from here on ends a command quietly (see ctrl_c.py)

from launch._missing import module_getattr
from launch_ros import actions, parameter_descriptions, substitutions

__all__ = ["actions", "parameter_descriptions", "substitutions"]
__getattr__ = module_getattr("launch_ros", lambda: __all__)
