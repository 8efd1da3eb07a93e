"""Reading a rosbag2 bag: a folder with metadata.yaml and its .mcap files (or one .mcap file),
described without reading its messages (Bag: what info and play need), and its messages in
log-time order across its files."""

from __future__ import annotations

import contextlib
import heapq
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from rosbag2.errors import BagError
from rosbag2.loss import lost_in
from rosbag2.mcap_file import PROFILE, BagMessage, McapFile
from rosbag2.metadata import METADATA_FILE, STORAGE_ID, TopicInfo, load_metadata
from rosbag2.offered_qos import safe_qos


@dataclass
class Bag:
    """What info and play need to know about a bag, without reading its messages."""

    path: Path
    files: list[Path]
    topics: dict[str, TopicInfo]
    message_count: int
    start: int
    end: int
    size: int
    ros_distro: str
    storage_id: str
    chunk_count: int
    complete: bool  # every file had its summary (False: scanned, e.g. a killed recording)
    version: str = ""  # of the rosbag2 metadata ("" for a lone .mcap file)
    warnings: list[str] = field(default_factory=list)
    lost: dict[str, int] = field(default_factory=dict)  # per topic, before recording (loss.py)

    @property
    def duration(self) -> int:
        return self.end - self.start


class BagReader:
    """Open a bag (a folder with metadata.yaml, or one .mcap file) and read it."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        if not self.path.exists():
            raise BagError(f"{self.path} does not exist")
        metadata: dict[str, Any] = {}
        if self.path.is_dir():
            metadata = load_metadata(self.path)
            storage = metadata.get("storage_identifier", "")
            if storage != STORAGE_ID:
                raise BagError(
                    f"{self.path} uses storage '{storage}'; only rosbag2's mcap storage "
                    "(ROS 2 Jazzy's default) is supported"
                )
            names = metadata.get("relative_file_paths") or []
            if not isinstance(names, list) or not names:
                raise BagError(f"{self.path / METADATA_FILE} lists no files")
            paths = [self.path / str(name) for name in names]
            for file_path in paths:
                if not file_path.is_file():
                    raise BagError(f"{file_path} is missing (listed in {METADATA_FILE})")
        else:
            paths = [self.path]
        self.files: list[McapFile] = []
        try:
            for file_path in paths:
                self.files.append(McapFile(file_path))
        except BagError:
            self.close()
            raise
        self.metadata = metadata
        self.bag = self._describe()

    def __enter__(self) -> BagReader:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        for mcap_file in self.files:
            mcap_file.close()

    def _describe(self) -> Bag:
        topics: dict[str, TopicInfo] = {}
        meta_topics = {}
        for item in self.metadata.get("topics_with_message_count") or []:
            with contextlib.suppress(AttributeError, TypeError, KeyError):
                meta_topics[item["topic_metadata"]["name"]] = item["topic_metadata"]
        warnings = []
        for mcap_file in self.files:
            if mcap_file.profile != PROFILE:
                warnings.append(
                    f"{mcap_file.path.name}: MCAP profile '{mcap_file.profile}', not '{PROFILE}'"
                )
            if not mcap_file.complete:
                warnings.append(
                    f"{mcap_file.path.name} has no summary (its recording did not finish); "
                    f"read {mcap_file.message_count} messages up to its last complete chunk"
                )
            for channel_id, channel in mcap_file.channels.items():
                schema = mcap_file.schemas.get(channel.schema_id)
                topic = topics.get(channel.topic)
                if topic is None:
                    meta = meta_topics.get(channel.topic, {})
                    qos = channel.metadata.get(
                        "offered_qos_profiles", meta.get("offered_qos_profiles")
                    )
                    topic = topics[channel.topic] = TopicInfo(
                        name=channel.topic,
                        type=schema.name if schema else meta.get("type", ""),
                        offered_qos_profiles=safe_qos(qos),
                        type_description_hash=channel.metadata.get(
                            "topic_type_hash", meta.get("type_description_hash", "")
                        )
                        or "",
                        serialization_format=channel.message_encoding,
                    )
                topic.message_count += mcap_file.counts.get(channel_id, 0)
        counted = [f for f in self.files if f.message_count]
        distro = self.metadata.get("ros_distro") or ""
        if not distro:
            for mcap_file in self.files:
                for record in mcap_file.rosbag2_metadata():
                    with contextlib.suppress(yaml.YAMLError, AttributeError):
                        text = record.get("serialized_metadata", "")
                        distro = (yaml.safe_load(text) or {}).get("ros_distro") or distro
        return Bag(
            path=self.path,
            files=[f.path for f in self.files],
            topics=topics,
            message_count=sum(f.message_count for f in self.files),
            start=min((f.start for f in counted), default=0),
            end=max((f.end for f in counted), default=0),
            size=_size(self.path),
            ros_distro=str(distro),
            storage_id=STORAGE_ID,
            chunk_count=sum(f.chunk_count for f in self.files),
            complete=all(f.complete for f in self.files),
            version=str(self.metadata.get("version", "")),
            warnings=warnings,
            lost=lost_in(self.metadata.get("custom_data")),
        )

    def messages(self, topics: Iterable[str] | None = None, start: int = 0) -> Iterator[BagMessage]:
        """All messages (of the given topics, from `start` ns on) in log-time order."""
        wanted = set(topics) if topics is not None else None
        streams = [f.messages(wanted, start) for f in self.files]
        if len(streams) == 1:
            yield from streams[0]
            return
        yield from heapq.merge(*streams, key=lambda m: m.log_time)


def _size(path: Path) -> int:
    if path.is_file():
        return path.stat().st_size
    return sum(p.stat().st_size for p in path.iterdir() if p.is_file())
