"""launch_ros.descriptions: ComposableNode is not here (see launch/_missing.py)."""

from launch._missing import module_getattr

__getattr__ = module_getattr("launch_ros.descriptions", lambda: [])
