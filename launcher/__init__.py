"""The launcher: runs ROS 1 (roslaunch) XML files and ROS 2 launch files in XML, YAML, Python.

    python -m launcher union.launch [name:=value ...] [--screen] [--print] [--show-args]

The top floor of the launch stack: it loads files (and their includes), has the model
(``launch``, ``launch_ros``) and its front-ends build and execute the entities, and plans and
supervises the processes they declare. It stands on ``launch_foundation`` (declarations,
naming, markup, expressions, errors); ``LaunchError`` is the one error type every stage raises
for bad input, re-exported here for the launcher's callers.
"""

from launch_foundation.errors import CodeRefused, LaunchError

__all__ = ["CodeRefused", "LaunchError"]
