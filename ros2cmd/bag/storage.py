"""rosbag2 bags in MCAP storage: a folder with metadata.yaml and one or more .mcap files.

The container itself (records, chunks, indexes, summary, CRCs) is the ``mcap`` package's,
the reference implementation of MCAP. This module adds what rosbag2 puts around it, as
ROS 2 Jazzy's ``ros2 bag record`` writes it with its default (mcap) storage plugin:

- the ``ros2`` profile, schemas in ``ros2msg`` encoding (definitions.py), messages in ``cdr``;
- per channel the metadata ``offered_qos_profiles`` (the publishers' QoS as YAML) and
  ``topic_type_hash`` (RIHS01_...); a ``rosbag2`` metadata record holding the bag's metadata;
- ``metadata.yaml`` (rosbag2 metadata version 9) beside the .mcap file; chunks uncompressed.

And what a recorder needs and the container leaves open: the chunk in progress is written out
at least every ``flush_period`` seconds (and metadata.yaml with it), so that a recorder killed
with SIGKILL leaves everything but the last period readable; a write that fails (``ENOSPC``)
cuts the file back to its last complete chunk, so the part written stays readable.

Reading takes the summary at the end of each file (no scan of the messages) and falls back
to scanning a file without one (a recording that was killed), up to its last complete record.
"""

from __future__ import annotations

import contextlib
import datetime
import heapq
import io
import itertools
import os
import struct
import time
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml
from mcap.data_stream import ReadDataStream
from mcap.exceptions import EndOfFile, McapError
from mcap.opcode import Opcode
from mcap.reader import FOOTER_SIZE, SeekingReader
from mcap.records import (
    Channel,
    Chunk,
    Footer,
    Message,
    Metadata,
    MetadataIndex,
    Schema,
    Statistics,
    SummaryOffset,
)
from mcap.stream_reader import MAGIC_SIZE, StreamReader, breakup_chunk
from mcap.writer import CompressionType, Writer

from ros2cmd.bag.loss import lost_in
from ros2cmd.errors import ToolError
from ros_tutorials_common import bounded

METADATA_FILE = "metadata.yaml"
MAX_METADATA_BYTES = bounded.MAX_INPUT_BYTES  # about 5,000 topics' metadata.yaml
MAX_FILE_NAME = 255  # bytes in a file name on Linux file systems
METADATA_VERSION = 9  # what rosbag2 0.26 (Jazzy) writes
STORAGE_ID = "mcap"
PROFILE = "ros2"
MESSAGE_ENCODING = "cdr"
LIBRARY = "ros-tutorials ros2 bag (python mcap)"
CHUNK_SIZE = 768 * 1024  # the C++ mcap writer's default, which rosbag2 keeps
FLUSH_PERIOD = 1.0  # seconds: the most a SIGKILL can lose
NS = 1_000_000_000

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


class BagError(ToolError):
    """A bag that cannot be read or written; the message names the file and the reason."""


# QoS <-> rosbag2's YAML


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


class _Dumper(yaml.SafeDumper):
    """Block style with indented sequences, as yaml-cpp writes rosbag2's files."""

    def increase_indent(self, flow: bool = False, indentless: bool = False) -> None:
        super().increase_indent(flow, False)


def _represent_none(dumper: yaml.SafeDumper, _data: None) -> Any:
    return dumper.represent_scalar("tag:yaml.org,2002:null", "~")


_Dumper.add_representer(type(None), _represent_none)


def dump_yaml(data: Any) -> str:
    return yaml.dump(data, Dumper=_Dumper, sort_keys=False, default_flow_style=False, width=1000)


# Metadata


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


def write_metadata_file(folder: Path, metadata: dict[str, Any]) -> None:
    """metadata.yaml, replaced in one step: a reader never sees half a file."""
    text = dump_yaml({"rosbag2_bagfile_information": metadata})
    temporary = folder / f".{METADATA_FILE}.tmp"
    try:
        temporary.write_text(text)
        os.replace(temporary, folder / METADATA_FILE)
    except OSError:
        with contextlib.suppress(OSError):
            temporary.unlink()
        raise


# Writing


class _File:
    """The .mcap file, unbuffered: what the mcap writer hands over reaches the OS at once.

    The writer needs only write, tell and flush. ``good_offset`` is where the last complete
    chunk ended: a failed write cuts the file back to it.
    """

    def __init__(self, path: Path) -> None:
        # O_EXCL: never overwrite, even a file someone created meanwhile.
        self.fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
        self.offset = 0
        self.good_offset = 0

    def write(self, data: bytes) -> int:
        view = memoryview(data)
        while view:
            written = os.write(self.fd, view)
            self.offset += written
            view = view[written:]
        return len(data)

    def tell(self) -> int:
        return self.offset

    def flush(self) -> None:
        pass  # nothing is buffered here

    def close(self) -> None:
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1


def bag_file_name(folder: Path, index: int = 0) -> str:
    """rosbag2's name for the index-th file of a bag: <folder name>_<index>.mcap."""
    return f"{folder.name}_{index}.mcap"


def default_bag_name() -> str:
    """rosbag2's default: rosbag2_YYYY_MM_DD-HH_MM_SS (local time)."""
    return datetime.datetime.now().strftime("rosbag2_%Y_%m_%d-%H_%M_%S")


def _shown(path: Path | str, most: int = 120) -> str:
    """A path for an error line: a 5,000-character name shows its start and its length."""
    text = str(path)
    return text if len(text) <= most else f"{text[:most]}... ({len(text)} characters)"


class BagWriter:
    """Write one rosbag2 bag: a new folder, its .mcap file and metadata.yaml.

    Call add_topic() before writing a topic's messages, write() for each message (the
    serialized CDR bytes as received), close() at the end. A failed write raises BagError
    after cutting the file back to its last complete chunk; close() is then still safe.
    """

    def __init__(
        self,
        folder: str | Path,
        ros_distro: str | None = None,
        chunk_size: int = CHUNK_SIZE,
        flush_period: float = FLUSH_PERIOD,
        custom_data: dict[str, str] | None = None,
    ) -> None:
        self.folder = Path(folder)
        self.custom_data = custom_data
        try:
            self.folder.mkdir(parents=True)
        except FileExistsError:
            raise BagError(
                f"{_shown(self.folder)} already exists; not overwriting it (choose another -o)"
            ) from None
        except OSError as error:  # a name too long, a folder that cannot be written
            raise BagError(f"cannot create {_shown(self.folder)}: {error.strerror}") from None
        self.file_info = FileInfo(bag_file_name(self.folder))
        self.path = self.folder / self.file_info.path
        if ros_distro is None:  # rosbag2 takes it from the environment of a sourced ROS
            ros_distro = os.environ.get("ROS_DISTRO", "jazzy")
        self.ros_distro = ros_distro
        self.topics: dict[str, TopicInfo] = {}
        self.channels: dict[str, int] = {}
        self.schemas: dict[str, int] = {}
        self.flush_period = flush_period
        self.failed: BagError | None = None
        self.closed = False
        self._last_flush = time.monotonic()
        self._end_time = 0
        # What was complete on disk at the last flush: metadata.yaml says that much.
        self._flushed = (FileInfo(self.file_info.path), {})
        self._file = _File(self.path)
        self._mcap = Writer(
            self._file,  # type: ignore[arg-type]
            chunk_size=chunk_size,
            compression=CompressionType.NONE,
            enable_crcs=True,
        )
        self._guard(self._start)

    def _start(self) -> None:
        self._mcap.start(profile=PROFILE, library=LIBRARY)
        # rosbag2 writes its metadata record when the file opens and again when it closes.
        self._mcap.add_metadata("rosbag2", {"serialized_metadata": dump_yaml(self.metadata())})
        write_metadata_file(self.folder, self.metadata())

    @property
    def message_count(self) -> int:
        return self.file_info.message_count

    def metadata(self, flushed: bool = False) -> dict[str, Any]:
        if flushed:
            file_info, counts = self._flushed
            topics = [
                TopicInfo(**{**t.__dict__, "message_count": counts.get(t.name, 0)})
                for t in self.topics.values()
            ]
            return bag_metadata(topics, [file_info], self.ros_distro, self.custom_data)
        return bag_metadata(
            self.topics.values(), [self.file_info], self.ros_distro, self.custom_data
        )

    def add_topic(self, topic: TopicInfo, definition: str, schema_encoding: str) -> None:
        """A topic's channel (and its type's schema, once per type)."""
        if topic.name in self.channels:
            return
        schema_id = self.schemas.get(topic.type)
        if schema_id is None:
            schema_id = self._guard(
                self._mcap.register_schema, topic.type, schema_encoding, definition.encode()
            )
            self.schemas[topic.type] = schema_id
        channel_metadata = {
            "offered_qos_profiles": dump_yaml(topic.offered_qos_profiles).rstrip("\n")
            if topic.offered_qos_profiles
            else "",
            "topic_type_hash": topic.type_description_hash,
        }
        self.channels[topic.name] = self._guard(
            self._mcap.register_channel,
            topic.name,
            topic.serialization_format,
            schema_id,
            channel_metadata,
        )
        self.topics[topic.name] = topic

    def write(self, topic: str, data: bytes, log_time: int, publish_time: int) -> None:
        """One message: its serialized bytes, receive time (log time) and send time (ns)."""
        if self.failed:
            raise self.failed
        offset = self._file.offset
        self._guard(self._mcap.add_message, self.channels[topic], log_time, data, publish_time)
        info = self.file_info
        if info.message_count == 0:
            info.starting_time = log_time
        elif log_time < info.starting_time:
            info.duration += info.starting_time - log_time
            info.starting_time = log_time
        self._end_time = max(self._end_time, log_time)
        info.duration = self._end_time - info.starting_time
        info.message_count += 1
        self.topics[topic].message_count += 1
        if self._file.offset != offset:  # a full chunk went out, this message in it
            self._remember_flushed()
        self.flush_if_due()

    def flush_if_due(self) -> None:
        if time.monotonic() - self._last_flush >= self.flush_period:
            self.flush()

    def flush(self) -> None:
        """Write the chunk in progress and metadata.yaml: all so far survives a SIGKILL."""
        if self.failed:
            raise self.failed
        self._last_flush = time.monotonic()
        self._guard(self._mcap.flush)
        self._remember_flushed()
        self._guard(write_metadata_file, self.folder, self.metadata())

    def _remember_flushed(self) -> None:
        """What is on disk now: the counts a failure later would leave readable."""
        self._flushed = (
            FileInfo(**self.file_info.__dict__),
            {name: t.message_count for name, t in self.topics.items()},
        )

    def close(self) -> None:
        """Finish the file (summary, footer) and write the final metadata.yaml."""
        if self.closed:
            return
        self.closed = True
        if self.failed:
            self._file.close()
            return
        try:
            self._guard(
                self._mcap.add_metadata,
                "rosbag2",
                {"serialized_metadata": dump_yaml(self.metadata())},
            )
            self._guard(self._mcap.finish)
            self._guard(os.fsync, self._file.fd)
            self._file.close()
            self._guard(write_metadata_file, self.folder, self.metadata())
        finally:
            self._file.close()

    def _guard(self, function: Any, *args: Any) -> Any:
        """Run a write; on failure keep what is complete and raise one BagError."""
        try:
            result = function(*args)
        except OSError as error:
            self.failed = self._fail(error)
            raise self.failed from None
        if self._file.fd >= 0:  # each call of the mcap writer ends at a record boundary
            self._file.good_offset = self._file.offset
        return result

    def _fail(self, error: OSError) -> BagError:
        kept = self._flushed[0].message_count
        reason = error.strerror or str(error)
        if self._file.fd >= 0:
            # Cut off the chunk that was being written: the file ends after a complete one.
            with contextlib.suppress(OSError):
                os.ftruncate(self._file.fd, self._file.good_offset)
                os.fsync(self._file.fd)
        with contextlib.suppress(OSError):
            write_metadata_file(self.folder, self.metadata(flushed=True))
        return BagError(
            f"cannot write {self.path}: {reason}; recording stopped, the {kept} messages "
            "written before stay readable"
        )


# Reading


@dataclass
class BagMessage:
    topic: str
    data: bytes
    log_time: int
    publish_time: int


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


def _load_metadata(folder: Path) -> dict[str, Any]:
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
        raise BagError(f"cannot read {path}: {_short(error)}") from None
    if not isinstance(data, dict) or not isinstance(data.get("rosbag2_bagfile_information"), dict):
        raise BagError(f"{path} is not rosbag2 metadata (no rosbag2_bagfile_information)")
    metadata = data["rosbag2_bagfile_information"]
    problem = _metadata_problem(metadata)
    if problem:
        raise BagError(f"{path}: {problem}")
    return metadata


def _metadata_problem(metadata: dict[str, Any]) -> str | None:
    """What in rosbag2 metadata does not have the shape rosbag2 writes, as one line."""
    names = metadata.get("relative_file_paths")
    if names is not None and (
        not isinstance(names, list) or not all(isinstance(n, str) for n in names)
    ):
        return "relative_file_paths is not a list of file names"
    for name in names or []:
        if not name or len(name) > MAX_FILE_NAME or "/" in name or name in (".", ".."):
            return f"relative_file_paths names '{_shown(name, 60)}', not a file of the bag's folder"
    topics = metadata.get("topics_with_message_count")
    if topics is not None and not (
        isinstance(topics, list) and all(isinstance(item, dict) for item in topics)
    ):
        return "topics_with_message_count is not a list of topics"
    for key in ("storage_identifier", "ros_distro"):
        if key in metadata and not isinstance(metadata[key], str | None):
            return f"{key} is not a string"
    return None


def _short(error: BaseException) -> str:
    return str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__


_READ_ERRORS = (McapError, struct.error, ValueError, EOFError, OSError, KeyError)
_SUMMARY_GROUPS = (Opcode.SCHEMA, Opcode.CHANNEL, Opcode.STATISTICS, Opcode.METADATA_INDEX)


class _McapFile:
    """One .mcap file: its summary, or what a scan up to its last complete record finds."""

    def __init__(self, path: Path) -> None:
        self.path = path
        try:
            self.stream = open(path, "rb")  # noqa: SIM115 (closed by close())
        except OSError as error:
            raise BagError(f"cannot open {path}: {error.strerror}") from None
        self.schemas: dict[int, Schema] = {}
        self.channels: dict[int, Channel] = {}
        self.counts: dict[int, int] = {}
        self.metadata_offsets: list[int] = []
        self.start = self.end = 0
        self.message_count = 0
        self.chunk_count = 0
        self.complete = True
        self.profile = ""
        try:
            self.reader = SeekingReader(self.stream, validate_crcs=True)
            self.profile = self.reader.get_header().profile
        except _READ_ERRORS as error:
            self.stream.close()
            raise BagError(f"{path} is not an MCAP file ({_short(error)})") from None
        statistics = None
        with contextlib.suppress(*_READ_ERRORS):
            statistics = self._read_summary()
        if statistics is not None:
            self.counts = dict(statistics.channel_message_counts)
            self.message_count = statistics.message_count
            self.start, self.end = statistics.message_start_time, statistics.message_end_time
            self.chunk_count = statistics.chunk_count
        else:
            self.complete = False
            for _ in self._scan():  # counts, times, schemas and channels of the complete part
                pass

    def _read_summary(self) -> Statistics | None:
        """Schemas, channels, statistics and metadata offsets, and nothing else.

        The summary's offsets say where each group is, so the chunk indexes (most of the
        summary of a large bag) are not even parsed: `info` needs none of them.
        """
        stream = self.stream
        stream.seek(-(FOOTER_SIZE + MAGIC_SIZE), io.SEEK_END)
        footer = next(StreamReader(stream, skip_magic=True).records)
        if not isinstance(footer, Footer) or footer.summary_start == 0:
            return None
        groups: dict[int, tuple[int, int]] = {}
        if footer.summary_offset_start:
            stream.seek(footer.summary_offset_start)
            for record in StreamReader(stream, skip_magic=True).records:
                if isinstance(record, SummaryOffset):
                    groups[record.group_opcode] = (record.group_start, record.group_length)
        if not all(opcode in groups for opcode in _SUMMARY_GROUPS[:3]):
            summary = self.reader.get_summary()  # no offsets: read the whole summary
            if summary is None:
                return None
            self.schemas, self.channels = dict(summary.schemas), dict(summary.channels)
            self.metadata_offsets = [index.offset for index in summary.metadata_indexes]
            return summary.statistics
        statistics = None
        for opcode in _SUMMARY_GROUPS:
            if opcode not in groups:
                continue
            start, length = groups[opcode]
            stream.seek(start)
            data = io.BytesIO(stream.read(length))
            with contextlib.suppress(EndOfFile):
                for record in StreamReader(data, skip_magic=True).records:
                    if isinstance(record, Schema):
                        self.schemas[record.id] = record
                    elif isinstance(record, Channel):
                        self.channels[record.id] = record
                    elif isinstance(record, Statistics):
                        statistics = record
                    elif isinstance(record, MetadataIndex):
                        self.metadata_offsets.append(record.offset)
        return statistics

    def rosbag2_metadata(self) -> list[dict[str, str]]:
        """The `rosbag2` metadata records of the file (rosbag2 writes one at open and close)."""
        found = []
        for offset in self.metadata_offsets:
            with contextlib.suppress(*_READ_ERRORS):
                self.stream.seek(offset)
                record = next(StreamReader(self.stream, skip_magic=True).records)
                if isinstance(record, Metadata) and record.name == "rosbag2":
                    found.append(record.metadata)
        return found

    def _scan(self) -> Iterator[tuple[Channel, Message]]:
        """Every record up to the end, or up to the first incomplete or damaged one."""
        self.stream.seek(0)
        counts: dict[int, int] = {}
        start = end = count = 0
        records = StreamReader(self.stream, validate_crcs=True).records
        with contextlib.suppress(*_READ_ERRORS):
            for record in records:
                if isinstance(record, Schema):
                    self.schemas[record.id] = record
                elif isinstance(record, Channel):
                    self.channels[record.id] = record
                elif isinstance(record, Message) and record.channel_id in self.channels:
                    counts[record.channel_id] = counts.get(record.channel_id, 0) + 1
                    start = record.log_time if count == 0 else min(start, record.log_time)
                    end = max(end, record.log_time)
                    count += 1
                    yield self.channels[record.channel_id], record
        if not self.complete:
            self.counts, self.start, self.end, self.message_count = counts, start, end, count

    def messages(self, topics: set[str] | None, start: int = 0) -> Iterator[BagMessage]:
        """The messages from `start` (ns) on, in log-time order (a killed recording's: in
        the order written)."""
        if not self.complete:
            for channel, message in self._scan():
                if (topics is None or channel.topic in topics) and message.log_time >= start:
                    yield BagMessage(
                        channel.topic, message.data, message.log_time, message.publish_time
                    )
            return
        try:
            yield from self._indexed_messages(topics, start)
        except _READ_ERRORS as error:
            raise BagError(f"{self.path} is damaged: {_short(error)}") from None

    def _indexed_messages(self, topics: set[str] | None, start: int) -> Iterator[BagMessage]:
        summary = self.reader.get_summary()
        assert summary is not None
        wanted = {
            channel_id
            for channel_id, channel in summary.channels.items()
            if topics is None or channel.topic in topics
        }
        chunks = sorted(summary.chunk_indexes, key=lambda index: index.chunk_start_offset)
        in_order = all(
            b.message_start_time >= a.message_end_time for a, b in itertools.pairwise(chunks)
        )
        if not in_order:  # overlapping chunks: the mcap reader merges them (slower)
            for _schema, channel, message in self.reader.iter_messages(
                topics=sorted(topics) if topics is not None else None,
                log_time_order=True,
                start_time=start,
            ):
                yield BagMessage(
                    channel.topic, message.data, message.log_time, message.publish_time
                )
            return
        # Chunks one after the other in time (what a recorder writes): sort within each.
        for index in chunks:
            if index.message_end_time < start:  # --start-offset: not even read
                continue
            if wanted.isdisjoint(index.message_index_offsets) and index.message_index_offsets:
                continue
            self.stream.seek(index.chunk_start_offset + 1 + 8)
            chunk = Chunk.read(ReadDataStream(self.stream))
            found = [
                record
                for record in breakup_chunk(chunk, validate_crc=True)
                if isinstance(record, Message)
                and record.channel_id in wanted
                and record.log_time >= start
            ]
            found.sort(key=lambda message: message.log_time)
            for message in found:
                topic = summary.channels[message.channel_id].topic
                yield BagMessage(topic, message.data, message.log_time, message.publish_time)

    def close(self) -> None:
        self.stream.close()


class BagReader:
    """Open a bag (a folder with metadata.yaml, or one .mcap file) and read it."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        if not self.path.exists():
            raise BagError(f"{self.path} does not exist")
        metadata: dict[str, Any] = {}
        if self.path.is_dir():
            metadata = _load_metadata(self.path)
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
        self.files: list[_McapFile] = []
        try:
            for file_path in paths:
                self.files.append(_McapFile(file_path))
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
                        offered_qos_profiles=_safe_qos(qos),
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


def _safe_qos(data: Any) -> list[dict[str, Any]]:
    try:
        return qos_profiles_from_yaml(data)
    except (yaml.YAMLError, AttributeError, TypeError):
        return []


def _size(path: Path) -> int:
    if path.is_file():
        return path.stat().st_size
    return sum(p.stat().st_size for p in path.iterdir() if p.is_file())


# Repair


def reindex(path: str | Path) -> Bag:
    """Give every file of a bag whose recording did not finish its summary, and the bag an
    up-to-date metadata.yaml (`rosbag reindex`, `ros2 bag reindex`).

    A file without a summary (a killed recorder, a full disk) is rewritten from its complete
    part: the same schemas, channels and messages, then the summary and footer that readers
    such as `rosbags` require. What was lost with the unfinished chunk stays lost.
    """
    folder = Path(path)
    with BagReader(folder) as reader:
        if not folder.is_dir():
            raise BagError(f"{folder} is not a bag folder (reindex works on a bag's folder)")
        for mcap_file in reader.files:
            if not mcap_file.complete:
                _rewrite_with_summary(mcap_file)
    with BagReader(folder) as reader:  # read again: now from the summaries
        bag = reader.bag
        files = [
            FileInfo(f.path.name, f.start, f.end - f.start, f.message_count) for f in reader.files
        ]
        distro = bag.ros_distro or str(reader.metadata.get("ros_distro", ""))
    write_metadata_file(folder, bag_metadata(bag.topics.values(), files, distro))
    return bag


def _rewrite_with_summary(mcap_file: _McapFile) -> None:
    temporary = mcap_file.path.with_name(mcap_file.path.name + ".reindex")
    try:
        with open(temporary, "wb") as stream:
            writer = Writer(stream, chunk_size=CHUNK_SIZE, compression=CompressionType.NONE)
            writer.start(profile=mcap_file.profile or PROFILE, library=LIBRARY)
            schema_ids: dict[int, int] = {}
            channel_ids: dict[int, int] = {}
            for channel, message in mcap_file._scan():
                if channel.id not in channel_ids:
                    schema = mcap_file.schemas.get(channel.schema_id)
                    if schema is not None and schema.id not in schema_ids:
                        schema_ids[schema.id] = writer.register_schema(
                            schema.name, schema.encoding, schema.data
                        )
                    channel_ids[channel.id] = writer.register_channel(
                        channel.topic,
                        channel.message_encoding,
                        schema_ids.get(channel.schema_id, 0),
                        dict(channel.metadata),
                    )
                writer.add_message(
                    channel_ids[channel.id],
                    message.log_time,
                    message.data,
                    message.publish_time,
                    message.sequence,
                )
            writer.finish()
            stream.flush()
            os.fsync(stream.fileno())
        os.replace(temporary, mcap_file.path)
    except OSError as error:
        with contextlib.suppress(OSError):
            temporary.unlink()
        raise BagError(f"cannot rewrite {mcap_file.path}: {error.strerror}") from None
