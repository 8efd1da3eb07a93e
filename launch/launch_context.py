"""launch.launch_context: LaunchContext, where ros2/launch has it."""

from launch._base import LaunchContext

__all__ = ["LaunchContext"]
