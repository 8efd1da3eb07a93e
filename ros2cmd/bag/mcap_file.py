"""One .mcap file of a bag, read back; and the MCAP settings rosbag2 writes its files with
(profile ``ros2``, chunk size), which the writer and reindex take from here.

The container itself (records, chunks, indexes, summary, CRCs) is the ``mcap`` package's,
the reference implementation of MCAP. Reading takes the summary at the end of the file (no
scan of the messages) and falls back to scanning a file without one (a recording that was
killed), up to its last complete record.
"""

from __future__ import annotations

import contextlib
import io
import itertools
import struct
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

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

from ros2cmd.bag.errors import BagError, short

PROFILE = "ros2"
LIBRARY = "ros-tutorials ros2 bag (python mcap)"
CHUNK_SIZE = 768 * 1024  # the C++ mcap writer's default, which rosbag2 keeps


@dataclass
class BagMessage:
    """One message as read from a bag: its topic, serialized bytes and times (ns)."""

    topic: str
    data: bytes
    log_time: int
    publish_time: int


READ_ERRORS = (McapError, struct.error, ValueError, EOFError, OSError, KeyError)
_SUMMARY_GROUPS = (Opcode.SCHEMA, Opcode.CHANNEL, Opcode.STATISTICS, Opcode.METADATA_INDEX)


class McapFile:
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
        except READ_ERRORS as error:
            self.stream.close()
            raise BagError(f"{path} is not an MCAP file ({short(error)})") from None
        statistics = None
        with contextlib.suppress(*READ_ERRORS):
            statistics = self._read_summary()
        if statistics is not None:
            self.counts = dict(statistics.channel_message_counts)
            self.message_count = statistics.message_count
            self.start, self.end = statistics.message_start_time, statistics.message_end_time
            self.chunk_count = statistics.chunk_count
        else:
            self.complete = False
            for _ in self.scan():  # counts, times, schemas and channels of the complete part
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
            with contextlib.suppress(*READ_ERRORS):
                self.stream.seek(offset)
                record = next(StreamReader(self.stream, skip_magic=True).records)
                if isinstance(record, Metadata) and record.name == "rosbag2":
                    found.append(record.metadata)
        return found

    def scan(self) -> Iterator[tuple[Channel, Message]]:
        """Every record up to the end, or up to the first incomplete or damaged one."""
        self.stream.seek(0)
        counts: dict[int, int] = {}
        start = end = count = 0
        records = StreamReader(self.stream, validate_crcs=True).records
        with contextlib.suppress(*READ_ERRORS):
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
            for channel, message in self.scan():
                if (topics is None or channel.topic in topics) and message.log_time >= start:
                    yield BagMessage(
                        channel.topic, message.data, message.log_time, message.publish_time
                    )
            return
        try:
            yield from self._indexed_messages(topics, start)
        except READ_ERRORS as error:
            raise BagError(f"{self.path} is damaged: {short(error)}") from None

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
                starting_at=start,  # mcap >= 1.6: start_time is its deprecated alias
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
