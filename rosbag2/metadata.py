"""metadata.yaml, rosbag2's BagMetadata (version 9, as ROS 2 Jazzy's rosbag2 writes it).

Its data (TopicInfo, FileInfo, bag_metadata()), its YAML as yaml-cpp writes it, its writing in
one step, and its reading: within bounded's limits, and checked for the shape rosbag2 writes
before any of it is used.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from ros_tutorials_common import bounded
from rosbag2.errors import BagError, short, shown

METADATA_FILE = "metadata.yaml"
MAX_METADATA_BYTES = bounded.MAX_INPUT_BYTES  # about 5,000 topics' metadata.yaml
MAX_FILE_NAME = 255  # bytes in a file name on Linux file systems
METADATA_VERSION = 9  # what rosbag2 0.26 (Jazzy) writes
STORAGE_ID = "mcap"
MESSAGE_ENCODING = "cdr"
NS = 1_000_000_000


class _Dumper(yaml.SafeDumper):
    """Block style with indented sequences, as yaml-cpp writes rosbag2's files."""

    def increase_indent(self, flow: bool = False, indentless: bool = False) -> None:
        super().increase_indent(flow, False)

    def ignore_aliases(self, data: Any) -> bool:
        return True  # yaml-cpp writes no anchors: a value shared by two topics is written twice


def _represent_none(dumper: yaml.SafeDumper, _data: None) -> Any:
    return dumper.represent_scalar("tag:yaml.org,2002:null", "~")


_Dumper.add_representer(type(None), _represent_none)


def dump_yaml(data: Any) -> str:
    return yaml.dump(data, Dumper=_Dumper, sort_keys=False, default_flow_style=False, width=1000)


@dataclass
class TopicInfo:
    """One topic of a bag: rosbag2's TopicMetadata and its message count."""

    name: str
    type: str
    offered_qos_profiles: list[dict[str, Any]] = field(default_factory=list)
    type_description_hash: str = ""
    serialization_format: str = MESSAGE_ENCODING
    message_count: int = 0

    def metadata(self) -> dict[str, Any]:
        return {
            "topic_metadata": {
                "name": self.name,
                "type": self.type,
                "serialization_format": self.serialization_format,
                "offered_qos_profiles": self.offered_qos_profiles,
                "type_description_hash": self.type_description_hash,
            },
            "message_count": self.message_count,
        }


@dataclass
class FileInfo:
    path: str
    starting_time: int = 0
    duration: int = 0
    message_count: int = 0


def bag_metadata(
    topics: Iterable[TopicInfo],
    files: list[FileInfo],
    ros_distro: str = "",
    custom_data: dict[str, str] | None = None,
) -> dict[str, Any]:
    """rosbag2's BagMetadata as its yaml.hpp encodes it (the inner mapping of metadata.yaml)."""
    counted = [f for f in files if f.message_count]
    start = min((f.starting_time for f in counted), default=0)
    end = max((f.starting_time + f.duration for f in counted), default=0)
    return {
        "version": METADATA_VERSION,
        "storage_identifier": STORAGE_ID,
        "duration": {"nanoseconds": end - start},
        "starting_time": {"nanoseconds_since_epoch": start},
        "message_count": sum(f.message_count for f in files),
        "topics_with_message_count": [topic.metadata() for topic in topics],
        "compression_format": "",
        "compression_mode": "",
        "relative_file_paths": [f.path for f in files],
        "files": [
            {
                "path": f.path,
                "starting_time": {"nanoseconds_since_epoch": f.starting_time},
                "duration": {"nanoseconds": f.duration},
                "message_count": f.message_count,
            }
            for f in files
        ],
        "custom_data": custom_data or None,
        "ros_distro": ros_distro,
    }


_TOPIC_ITEMS: dict[str, str] = {}  # a topic's YAML in metadata.yaml up to its count
_COUNT_LINE = "      message_count: 0\n"
_EMPTY_TOPICS = "  topics_with_message_count: []\n"


def metadata_text(metadata: dict[str, Any]) -> str:
    """metadata.yaml's text: dump_yaml of it, with each topic's part rendered once.

    A recorder rewrites the file every second, and 50 topics' YAML took PyYAML 70 ms each
    time; only the counts change, so a topic's text is kept up to its count.
    """
    topics = metadata.get("topics_with_message_count")
    if not topics or not all(
        isinstance(t, dict) and list(t) == ["topic_metadata", "message_count"] for t in topics
    ):
        return dump_yaml({"rosbag2_bagfile_information": metadata})
    rest = dump_yaml({"rosbag2_bagfile_information": {**metadata, "topics_with_message_count": []}})
    items = "".join(
        f"{_topic_item(t['topic_metadata'])}      message_count: {t['message_count']}\n"
        for t in topics
    )
    return rest.replace(_EMPTY_TOPICS, f"  topics_with_message_count:\n{items}", 1)


def _topic_item(topic_metadata: dict[str, Any]) -> str:
    key = repr(topic_metadata)
    item = _TOPIC_ITEMS.get(key)
    if item is None:
        whole = dump_yaml(
            {
                "rosbag2_bagfile_information": {
                    "topics_with_message_count": [
                        {"topic_metadata": topic_metadata, "message_count": 0}
                    ]
                }
            }
        )
        item = whole.split("\n", 2)[2].removesuffix(_COUNT_LINE)
        if len(_TOPIC_ITEMS) >= 10_000:  # bounded: a long-running process records many bags
            _TOPIC_ITEMS.clear()
        _TOPIC_ITEMS[key] = item
    return item


def write_metadata_file(folder: Path, metadata: dict[str, Any]) -> None:
    """metadata.yaml, replaced in one step: a reader never sees half a file."""
    text = metadata_text(metadata)
    temporary = folder / f".{METADATA_FILE}.tmp"
    try:
        temporary.write_text(text)
        os.replace(temporary, folder / METADATA_FILE)
    except OSError:
        with contextlib.suppress(OSError):
            temporary.unlink()
        raise


def load_metadata(folder: Path) -> dict[str, Any]:
    """The inner mapping of a bag folder's metadata.yaml, read within bounded's limits and
    checked for rosbag2's shape; a BagError names what is wrong."""
    path = folder / METADATA_FILE
    if not path.is_file():
        mcaps = sorted(folder.glob("*.mcap"))
        hint = f" (to read its MCAP file alone, name it: {mcaps[0]})" if mcaps else ""
        raise BagError(f"{folder} is not a bag: it has no {METADATA_FILE}{hint}")
    try:  # within bounded's limits on size, aliases and nesting, like every file a user hands us
        data = bounded.load_yaml(bounded.read_text(path, MAX_METADATA_BYTES), str(path))
    except bounded.InputError as error:
        raise BagError(str(error)) from None
    except yaml.YAMLError as error:
        raise BagError(f"cannot read {path}: {short(error)}") from None
    if not isinstance(data, dict) or not isinstance(data.get("rosbag2_bagfile_information"), dict):
        raise BagError(f"{path} is not rosbag2 metadata (no rosbag2_bagfile_information)")
    metadata = data["rosbag2_bagfile_information"]
    problem = metadata_problem(metadata)
    if problem:
        raise BagError(f"{path}: {problem}")
    return metadata


def metadata_problem(metadata: dict[str, Any]) -> str | None:
    """What in rosbag2 metadata does not have the shape rosbag2 writes, as one line."""
    names = metadata.get("relative_file_paths")
    if names is not None and (
        not isinstance(names, list) or not all(isinstance(n, str) for n in names)
    ):
        return "relative_file_paths is not a list of file names"
    for name in names or []:
        if not name or len(name) > MAX_FILE_NAME or "/" in name or name in (".", ".."):
            return f"relative_file_paths names '{shown(name, 60)}', not a file of the bag's folder"
    topics = metadata.get("topics_with_message_count")
    if topics is not None and not (
        isinstance(topics, list) and all(isinstance(item, dict) for item in topics)
    ):
        return "topics_with_message_count is not a list of topics"
    for key in ("storage_identifier", "ros_distro"):
        if key in metadata and not isinstance(metadata[key], str | None):
            return f"{key} is not a string"
    return None
