"""launch.logging: the launch's loggers and where its log files go (``launch_config``), as
ros2/launch has them; ``get_logger(name)`` is a ``logging`` logger under ``launch``."""

from __future__ import annotations

import logging
import os
from pathlib import Path

__all__ = ["get_logger", "launch_config", "reset"]


class LaunchConfig:
    """The launch's logging settings: ``level`` and ``log_dir`` (made when first asked for:
    ``$ROS_LOG_DIR``, else ``$ROS_HOME/log``, else ``~/.ros/log``, then a folder of its own
    named by the time, the host and the process)."""

    def __init__(self) -> None:
        self.level = logging.INFO
        self._log_dir: str | None = None

    @property
    def log_dir(self) -> str:
        if self._log_dir is None:
            import datetime  # here: most launches never ask
            import socket

            base = os.environ.get("ROS_LOG_DIR") or os.path.join(
                os.environ.get("ROS_HOME") or os.path.join(os.path.expanduser("~"), ".ros"),
                "log",
            )
            stamp = datetime.datetime.now().strftime("%Y-%m-%d-%H-%M-%S-%f")
            folder = Path(base) / f"{stamp}-{socket.gethostname()}-{os.getpid()}"
            folder.mkdir(parents=True, exist_ok=True)
            self._log_dir = str(folder)
        return self._log_dir

    @log_dir.setter
    def log_dir(self, value: str | None) -> None:
        self._log_dir = None if value is None else str(value)

    def set_level(self, level: int) -> None:
        self.level = level
        logging.getLogger("launch").setLevel(level)


launch_config = LaunchConfig()


def get_logger(name: str | None = None) -> logging.Logger:
    """The logger ``launch`` (no name) or ``launch.NAME``... as ros2/launch names them."""
    return logging.getLogger(name or "launch")


def reset() -> None:
    """Forget the log folder and level (a new launch makes its own)."""
    launch_config.log_dir = None
    launch_config.level = logging.INFO
