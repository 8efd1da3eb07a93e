"""The DDS settings the user gave (read before rclpy.init, which applies this project's
defaults): ROS_DOMAIN_ID, ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_STATIC_PEERS, ROS_LOCALHOST_ONLY,
ROS_DISTRO."""

from __future__ import annotations

import os
from dataclasses import dataclass

from ros_tutorials_common.dds import DDS_DEFAULTS, MAX_DOMAIN_ID, domain_id

PORTABLE_DOMAIN_IDS = 101  # above, ports may meet the OS's ephemeral ports (ROS 2 docs)
RANGES = ("LOCALHOST", "SUBNET", "OFF", "SYSTEM_DEFAULT")


@dataclass
class Settings:
    domain_text: str | None
    range_text: str | None
    static_peers: str | None
    localhost_only: str | None
    ros_distro: str | None

    @classmethod
    def from_environment(cls) -> Settings:
        env = os.environ
        return cls(
            env.get("ROS_DOMAIN_ID"),
            env.get("ROS_AUTOMATIC_DISCOVERY_RANGE"),
            env.get("ROS_STATIC_PEERS"),
            env.get("ROS_LOCALHOST_ONLY"),
            env.get("ROS_DISTRO"),
        )

    @property
    def domain_id(self) -> int | None:
        """The domain id, or None if it is not one Fast DDS can use."""
        value = domain_id({"ROS_DOMAIN_ID": self.domain_text or ""})
        return None if value is None or value > MAX_DOMAIN_ID else value

    def domain_problem(self) -> str | None:
        if self.domain_id is not None:
            return None
        text = self.domain_text
        if domain_id({"ROS_DOMAIN_ID": text or ""}) is not None:
            what = f"is above {MAX_DOMAIN_ID}, the largest domain id Fast DDS can use"
        else:
            what = "is not a whole number in ASCII digits"
        return f"ROS_DOMAIN_ID={text!r} {what}: use one from 0 to {PORTABLE_DOMAIN_IDS}"

    @property
    def discovery_range(self) -> str:
        """The range every process here uses: the user's, else this project's default."""
        if self.localhost_only == "1":
            return "LOCALHOST"  # rcl honours the deprecated variable over the range
        if self.range_text is None:
            return DDS_DEFAULTS["ROS_AUTOMATIC_DISCOVERY_RANGE"]
        if not self.range_text:
            return "SUBNET"  # set but empty: rcl's own default
        return self.range_text if self.range_text in RANGES else "LOCALHOST"  # as rcl does

    def describe_range(self) -> str:
        text = self.discovery_range
        if self.localhost_only == "1":
            return f"{text} (ROS_LOCALHOST_ONLY=1)"
        if self.range_text is None:
            return f"{text} (this project's default)"
        if self.range_text and self.range_text not in RANGES:
            return f"{text} (rcl's reading of {self.range_text!r})"
        return text

    @property
    def subnet(self) -> bool:
        return self.discovery_range in ("SUBNET", "SYSTEM_DEFAULT")
