"""rosbag2_py._storage: the options and the topic description of rosbag2's Python API (Jazzy),
with the same names, fields and defaults as the real bindings."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

DEFAULT_STORAGE_ID = "mcap"  # ROS 2 Jazzy's default storage plugin, the only one here


@dataclass
class StorageOptions:
    """Where a bag is (``uri``: its folder) and how it is stored."""

    uri: str
    storage_id: str = ""  # "": the default, mcap
    max_bagfile_size: int = 0
    max_bagfile_duration: int = 0
    max_cache_size: int = 0
    storage_preset_profile: str = ""
    storage_config_uri: str = ""
    snapshot_mode: bool = False
    start_time_ns: int = -1
    end_time_ns: int = -1
    custom_data: dict[str, str] = field(default_factory=dict)


@dataclass
class ConverterOptions:
    """The serialization formats in and out; "" (or the same twice) means no conversion."""

    input_serialization_format: str = ""
    output_serialization_format: str = ""


@dataclass
class TopicMetadata:
    """A topic of a bag: its name, type (``std_msgs/msg/String``) and serialization format.

    ``offered_qos_profiles``: the publishers' QoS, as rclpy QoSProfile objects or as the
    dictionaries a bag's metadata holds (what the reader gives back)."""

    id: int
    name: str
    type: str
    serialization_format: str
    offered_qos_profiles: list[Any] = field(default_factory=list)
    type_description_hash: str = ""

    def equals(self, other: TopicMetadata) -> bool:
        return (
            self.name == other.name
            and self.type == other.type
            and self.serialization_format == other.serialization_format
            and self.offered_qos_profiles == other.offered_qos_profiles
            and self.type_description_hash == other.type_description_hash
        )


@dataclass
class StorageFilter:
    """Which messages a reader gives: by topic name (exactly) and by regular expression
    (matching the whole name); empty fields filter nothing."""

    topics: list[str] = field(default_factory=list)
    services_events: list[str] = field(default_factory=list)
    regex: str = ""
    exclude_topics: list[str] = field(default_factory=list)
    exclude_service_events: list[str] = field(default_factory=list)
    regex_to_exclude: str = ""


def get_default_storage_id() -> str:
    return DEFAULT_STORAGE_ID


def check_options(storage_id: str, converter_options: ConverterOptions | None) -> None:
    """Refuse, as rosbag2 does with a RuntimeError, what this environment cannot do."""
    if storage_id not in ("", DEFAULT_STORAGE_ID):
        raise RuntimeError(
            f"No storage could be initialized from the inputs: storage id '{storage_id}' "
            f"(this environment has only '{DEFAULT_STORAGE_ID}', ROS 2 Jazzy's default)"
        )
    if converter_options is None:
        return
    formats = {
        converter_options.input_serialization_format,
        converter_options.output_serialization_format,
    }
    if not formats <= {"", "cdr"}:
        raise RuntimeError(
            f"no converter for serialization formats {sorted(formats - {''})}: "
            "only 'cdr' is stored here"
        )
