"""Writing a rosbag2 bag as ROS 2 Jazzy's ``ros2 bag record`` does with its default (mcap)
storage plugin: a new folder, its .mcap file and metadata.yaml.

Per channel the metadata ``offered_qos_profiles`` (the publishers' QoS as YAML) and
``topic_type_hash`` (RIHS01_...); a ``rosbag2`` metadata record holding the bag's metadata;
chunks uncompressed. And what a recorder needs and the container leaves open: the chunk in
progress is written out at least every ``flush_period`` seconds (and metadata.yaml with it), so
that a recorder killed with SIGKILL leaves everything but the last period readable; a write
that fails (``ENOSPC``) cuts the file back to its last complete chunk, so the part written
stays readable.
"""

from __future__ import annotations

import contextlib
import datetime
import os
import time
from pathlib import Path
from typing import Any

from mcap.writer import CompressionType, Writer

from rosbag2.errors import BagError, shown
from rosbag2.mcap_file import CHUNK_SIZE, LIBRARY, PROFILE
from rosbag2.metadata import FileInfo, TopicInfo, bag_metadata, dump_yaml, write_metadata_file

FLUSH_PERIOD = 1.0  # seconds: the most a SIGKILL can lose


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


def _check_name_fits(folder: Path) -> None:
    """Refuse, before anything is created, a folder whose .mcap file's name the file system
    cannot hold (the file adds ``_0.mcap`` to the folder's name)."""
    name = bag_file_name(folder)
    parent = folder.parent
    while not os.path.isdir(parent) and parent != parent.parent:  # -o a/b/c: a may be new
        parent = parent.parent
    try:
        most = os.pathconf(parent, "PC_NAME_MAX")
    except (OSError, ValueError):
        most = 255  # Linux's NAME_MAX
    size = len(os.fsencode(name))
    if len(os.fsencode(folder.name)) <= most < size:  # a longer folder name: mkdir says so
        suffix = name[len(folder.name) :]
        raise BagError(
            f"cannot create {shown(folder)}: the name of its file (with '{suffix}') would be "
            f"{size} bytes, more than the {most} a file name can have here; choose a shorter name"
        )


def default_bag_name() -> str:
    """rosbag2's default: rosbag2_YYYY_MM_DD-HH_MM_SS (local time)."""
    return datetime.datetime.now().strftime("rosbag2_%Y_%m_%d-%H_%M_%S")


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
        _check_name_fits(self.folder)
        try:
            self.folder.mkdir(parents=True)
        except FileExistsError:
            raise BagError(
                f"{shown(self.folder)} already exists; not overwriting it (choose another -o)"
            ) from None
        except OSError as error:  # a name too long, a folder that cannot be written
            raise BagError(f"cannot create {shown(self.folder)}: {error.strerror}") from None
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
        self.write_many(topic, [(data, log_time, publish_time)])

    def write_many(self, topic: str, messages: list[tuple[bytes, int, int]]) -> None:
        """Messages of one topic, each (serialized bytes, receive time, send time) in ns.

        One call for a batch: at 50 topics x 1 kHz the per-message bookkeeping is most of what
        a recorder spends beside taking the messages.
        """
        if self.failed:
            raise self.failed
        if not messages:
            return
        channel = self.channels[topic]
        add_message = self._mcap.add_message
        file = self._file
        info = self.file_info
        start, end = info.starting_time, self._end_time
        if info.message_count == 0:
            start = messages[0][1]
        written = 0
        try:
            for data, log_time, publish_time in messages:
                offset = file.offset
                add_message(channel, log_time, data, publish_time)
                written += 1
                start = min(start, log_time)
                end = max(end, log_time)
                if file.offset != offset:  # a full chunk went out, this message in it
                    self._count(topic, written, start, end)
                    written = 0
                    self._remember_flushed()
        except OSError as error:
            self.failed = self._fail(error)
            raise self.failed from None
        finally:
            self._count(topic, written, start, end)
            if (
                file.fd >= 0 and not self.failed
            ):  # each call of the mcap writer ends at a record boundary
                file.good_offset = file.offset
        self.flush_if_due()

    def _count(self, topic: str, written: int, start: int, end: int) -> None:
        info = self.file_info
        info.starting_time = start
        self._end_time = end
        info.duration = end - start
        info.message_count += written
        self.topics[topic].message_count += written

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
