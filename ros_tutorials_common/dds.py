"""The one place that sets this project's DDS defaults.

Fast DDS multicasts discovery on every network interface unless told otherwise. The
tutorials keep their traffic on this machine: ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST,
unless the user has set it (e.g. SUBNET to talk to other machines). It must be applied
before rclpy.init(), which is when rcl reads it; the launcher passes it to its children.
"""

from __future__ import annotations

import os
from collections.abc import MutableMapping

DDS_DEFAULTS = {"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}


def apply_dds_defaults(env: MutableMapping[str, str] | None = None) -> MutableMapping[str, str]:
    """Fill in the DDS defaults the user has not set; return the environment."""
    if env is None:
        env = os.environ
    for name, value in DDS_DEFAULTS.items():
        env.setdefault(name, value)
    return env
