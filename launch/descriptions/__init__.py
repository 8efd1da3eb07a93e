"""launch.descriptions: descriptions of what an action runs (Executable)."""

from launch.descriptions.executable import Executable

__all__ = ["Executable"]
