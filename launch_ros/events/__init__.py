"""launch_ros.events: the lifecycle events launch files name (launch_ros.events.lifecycle)."""

from launch._missing import module_getattr
from launch_ros.events import lifecycle

__all__ = ["lifecycle"]
__getattr__ = module_getattr("launch_ros.events", lambda: __all__)
