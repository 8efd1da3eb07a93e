"""offered_qos_profiles: an rclpy QoSProfile as rosbag2 serialises it (metadata version 9,
rmw's policy names), and the profiles of a bag of any version read back (numbers before 9)."""

from __future__ import annotations

from typing import Any

import yaml

from rosbag2.metadata import NS

# QoS policies as rosbag2 serialises them since metadata version 9 (rmw's names), and the
# numbers older bags use (rmw's enum values).
HISTORY = {0: "system_default", 1: "keep_last", 2: "keep_all", 3: "unknown"}
RELIABILITY = {0: "system_default", 1: "reliable", 2: "best_effort", 3: "unknown",
               4: "best_available"}  # fmt: skip
DURABILITY = {0: "system_default", 1: "transient_local", 2: "volatile", 3: "unknown",
              4: "best_available"}  # fmt: skip
LIVELINESS = {0: "system_default", 1: "automatic", 3: "manual_by_topic", 4: "unknown",
              5: "best_available"}  # fmt: skip
INFINITE_NS = 9223372036854775807  # RMW_DURATION_INFINITE, as {sec: 9223372036, nsec: 854775807}


def qos_to_dict(qos: Any) -> dict[str, Any]:
    """An rclpy QoSProfile as rosbag2 (version 9) writes it in metadata and channel metadata."""

    def duration(value: Any) -> dict[str, int]:
        nanoseconds = min(int(value.nanoseconds), INFINITE_NS)
        return {"sec": nanoseconds // NS, "nsec": nanoseconds % NS}

    return {
        "history": HISTORY.get(int(qos.history), "unknown"),
        "depth": int(qos.depth),
        "reliability": RELIABILITY.get(int(qos.reliability), "unknown"),
        "durability": DURABILITY.get(int(qos.durability), "unknown"),
        "deadline": duration(qos.deadline),
        "lifespan": duration(qos.lifespan),
        "liveliness": LIVELINESS.get(int(qos.liveliness), "unknown"),
        "liveliness_lease_duration": duration(qos.liveliness_lease_duration),
        "avoid_ros_namespace_conventions": bool(qos.avoid_ros_namespace_conventions),
    }


def _policy(value: Any, names: dict[int, str]) -> str:
    """A policy as written by any metadata version: a name (>= 9) or a number (< 9)."""
    if isinstance(value, int):
        return names.get(value, "unknown")
    return str(value)


def qos_profiles_from_yaml(data: Any) -> list[dict[str, Any]]:
    """offered_qos_profiles of any rosbag2 version (a YAML string before 9, a list since)."""
    if isinstance(data, str):
        data = yaml.safe_load(data) if data.strip() else []
    profiles = []
    for item in data or []:
        if not isinstance(item, dict):
            continue
        profile = dict(item)
        for key, names in (
            ("history", HISTORY),
            ("reliability", RELIABILITY),
            ("durability", DURABILITY),
            ("liveliness", LIVELINESS),
        ):
            profile[key] = _policy(item.get(key, "unknown"), names)
        profiles.append(profile)
    return profiles


def safe_qos(data: Any) -> list[dict[str, Any]]:
    """qos_profiles_from_yaml(), or no profiles where the data is not theirs."""
    try:
        return qos_profiles_from_yaml(data)
    except (yaml.YAMLError, AttributeError, TypeError):
        return []
