"""One .mcap file of a bag, read back; and the MCAP settings rosbag2 writes its files with
(profile ``ros2``, chunk size), which the writer and reindex take from here.

The container itself (records, chunks, indexes, summary, CRCs) is the ``mcap`` package's,
the reference implementation of MCAP. Reading takes the summary at the end of the file (no
scan of the messages) and falls back to scanning a file without one (a recording that was
killed), up to its last complete record. Chunks are decompressed here, one at a time and
within a limit (chunk_records): the package's own reader allocates whatever size a chunk, or
the compressed frame inside it, declares.
"""

from __future__ import annotations

import contextlib
import dataclasses
import heapq
import io
import os
import struct
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import lz4.frame
import zstandard
from mcap.data_stream import ReadDataStream
from mcap.exceptions import EndOfFile, McapError
from mcap.opcode import Opcode
from mcap.reader import FOOTER_SIZE, SeekingReader
from mcap.records import (
    Channel,
    Chunk,
    Footer,
    McapRecord,
    Message,
    Metadata,
    MetadataIndex,
    Schema,
    Statistics,
    SummaryOffset,
)
from mcap.stream_reader import MAGIC_SIZE, StreamReader, breakup_chunk

from rosbag2.errors import BagError, short, shown

PROFILE = "ros2"
LIBRARY = "ros-tutorials ros2 bag (python mcap)"
CHUNK_SIZE = 768 * 1024  # the C++ mcap writer's default, which rosbag2 keeps
# A chunk is decompressed whole; a recorder's chunk is CHUNK_SIZE, or one larger message.
MAX_CHUNK_BYTES = 512 * 1024 * 1024
# What one file may declare: each channel is a topic that info lists and play may make a
# publisher for, each schema a type. MCAP's ids allow 65,535 of each.
MAX_CHANNELS = 10_000
MAX_SCHEMAS = 10_000


@dataclass
class BagMessage:
    """One message as read from a bag: its topic, serialized bytes and times (ns)."""

    topic: str
    data: bytes
    log_time: int
    publish_time: int


READ_ERRORS = (McapError, struct.error, ValueError, EOFError, OSError, KeyError)


class ChunkTooLarge(BagError):
    """A chunk that would decompress to more than MAX_CHUNK_BYTES: refused, not skipped."""


class TooManyDeclared(BagError):
    """More channels or schemas than MAX_CHANNELS or MAX_SCHEMAS, or one id declared twice
    as two different things: refused, not read on."""


class _BoundedFile(io.BufferedReader):
    """The file, whose reads never ask for more than is left in it: a length field of a
    damaged or crafted file (up to 2**64) allocates nothing larger than the file."""

    def __init__(self, path: Path) -> None:
        super().__init__(io.FileIO(path, "rb"))
        self.size = os.fstat(self.fileno()).st_size

    def read(self, size: int | None = -1, /) -> bytes:
        if size is not None and size > 0:
            size = min(size, max(self.size - self.tell(), 0))
            if size == 0:
                return b""
        return super().read(size)


def _named(record: Schema | Channel) -> str:
    text = record.name if isinstance(record, Schema) else record.topic
    return repr(text[:80] + "..." if len(text) > 80 else text)


def _decompressed(chunk: Chunk, source: Path) -> bytes:
    """A chunk's records section, decompressed to no more than its declared size, itself at
    most MAX_CHUNK_BYTES."""
    declared = chunk.uncompressed_size
    if declared > MAX_CHUNK_BYTES:
        raise ChunkTooLarge(
            f"{shown(source)}: a chunk declares {declared} bytes uncompressed, more than the "
            f"{MAX_CHUNK_BYTES // (1024 * 1024)} MiB a chunk may have here; refusing it"
        )
    if chunk.compression == "":
        data = chunk.data
    elif chunk.compression == "zstd":
        # Not zstandard.decompress: it allocates the size the frame's header declares.
        with zstandard.ZstdDecompressor().stream_reader(chunk.data) as stream:
            data = stream.read(declared + 1)  # up to that many bytes, or to the frame's end
    elif chunk.compression == "lz4":
        data = lz4.frame.LZ4FrameDecompressor().decompress(chunk.data, max_length=declared + 1)
    else:
        raise McapError(f"unsupported chunk compression '{chunk.compression}'")
    if len(data) != declared:
        what = "more" if len(data) > declared else f"{len(data)} bytes"
        raise McapError(f"a chunk decompresses to {what}, not the {declared} bytes it declares")
    return data


def chunk_records(chunk: Chunk, source: Path) -> list[McapRecord]:
    """The records of a chunk, decompressed within bounds (mcap's own breakup_chunk would
    allocate whatever size the chunk or its compressed frame declares)."""
    plain = dataclasses.replace(chunk, compression="", data=_decompressed(chunk, source))
    return breakup_chunk(plain, validate_crc=True)


_SUMMARY_GROUPS = (Opcode.SCHEMA, Opcode.CHANNEL, Opcode.STATISTICS, Opcode.METADATA_INDEX)


class McapFile:
    """One .mcap file: its summary, or what a scan up to its last complete record finds."""

    def __init__(self, path: Path) -> None:
        self.path = path
        if path.exists() and not path.is_file():  # a named pipe would block open() for good
            raise BagError(f"{shown(path)} is not a file")
        try:
            self.stream = _BoundedFile(path)
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
        try:
            with contextlib.suppress(*READ_ERRORS):
                statistics = self._read_summary()
        except BagError:
            self.stream.close()
            raise
        if statistics is not None:
            self.counts = dict(statistics.channel_message_counts)
            self.message_count = statistics.message_count
            self.start, self.end = statistics.message_start_time, statistics.message_end_time
            self.chunk_count = statistics.chunk_count
        else:
            self.complete = False
            try:
                for _ in self.scan():  # counts, times, schemas and channels of the complete part
                    pass
            except BagError:
                self.stream.close()
                raise

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
            for record in [*summary.schemas.values(), *summary.channels.values()]:
                self._declare(record)
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
                    if isinstance(record, (Schema, Channel)):
                        self._declare(record)
                    elif isinstance(record, Statistics):
                        statistics = record
                    elif isinstance(record, MetadataIndex):
                        self.metadata_offsets.append(record.offset)
        return statistics

    def _declare(self, record: Schema | Channel) -> None:
        """Keep a schema or channel record, within MAX_SCHEMAS and MAX_CHANNELS; the same
        record again (a summary repeats them) is nothing new."""
        if isinstance(record, Schema):
            known, most, what = self.schemas, MAX_SCHEMAS, "schema"
        else:
            known, most, what = self.channels, MAX_CHANNELS, "channel"
        before = known.get(record.id)
        if before == record:
            return
        if before is not None:
            raise TooManyDeclared(
                f"{shown(self.path)} is damaged: {what} id {record.id} is declared twice, "
                f"as {_named(before)} and as {_named(record)}"
            )
        if len(known) >= most:
            raise TooManyDeclared(
                f"{shown(self.path)} declares more than {most} {what}s; a bag here may "
                f"declare at most {most}: refusing it"
            )
        known[record.id] = record  # type: ignore[assignment]

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
        with contextlib.suppress(*READ_ERRORS):
            for record in self._records():
                if isinstance(record, (Schema, Channel)):
                    self._declare(record)
                elif isinstance(record, Message) and record.channel_id in self.channels:
                    counts[record.channel_id] = counts.get(record.channel_id, 0) + 1
                    start = record.log_time if count == 0 else min(start, record.log_time)
                    end = max(end, record.log_time)
                    count += 1
                    yield self.channels[record.channel_id], record
        if not self.complete:
            self.counts, self.start, self.end, self.message_count = counts, start, end, count

    def _records(self) -> Iterator[McapRecord]:
        """The file's records in order, each chunk's broken up within bounds."""
        for record in StreamReader(self.stream, emit_chunks=True, validate_crcs=True).records:
            if isinstance(record, Chunk):
                yield from chunk_records(record, self.path)
            else:
                yield record

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
        """Chunk by chunk in order of their start times; a message is given once no chunk
        still unread can hold an earlier one (chunks one after the other in time, as a
        recorder writes them, are each read only when the previous one is given)."""
        summary = self.reader.get_summary()
        assert summary is not None
        wanted = {
            channel_id
            for channel_id, channel in summary.channels.items()
            if topics is None or channel.topic in topics
        }
        chunks = sorted(
            (
                index
                for index in summary.chunk_indexes
                if index.message_end_time >= start  # --start-offset: not even read
                and not (
                    wanted.isdisjoint(index.message_index_offsets) and index.message_index_offsets
                )
            ),
            key=lambda index: (index.message_start_time, index.chunk_start_offset),
        )
        waiting: list[tuple[int, int, int, Message]] = []  # (log time, chunk, place, message)
        held = 0  # bytes of the messages waiting: bounded, whatever the chunk index claims

        def given() -> BagMessage:
            nonlocal held
            message = heapq.heappop(waiting)[3]
            held -= len(message.data)
            return self._bag_message(summary.channels, message)

        for position, index in enumerate(chunks):
            while waiting and waiting[0][0] < index.message_start_time:
                yield given()
            self.stream.seek(index.chunk_start_offset + 1 + 8)
            chunk = Chunk.read(ReadDataStream(self.stream))
            found = [
                record
                for record in chunk_records(chunk, self.path)
                if isinstance(record, Message)
                and record.channel_id in wanted
                and record.log_time >= start
            ]
            found.sort(key=lambda message: message.log_time)  # stable: ties keep their order
            later = chunks[position + 1].message_start_time if position + 1 < len(chunks) else None
            if not waiting and (not found or later is None or later > found[-1].log_time):
                # No other chunk can hold an earlier message (what a recorder writes).
                for message in found:
                    yield self._bag_message(summary.channels, message)
                continue
            for place, message in enumerate(found):
                heapq.heappush(
                    waiting, (message.log_time, index.chunk_start_offset, place, message)
                )
                held += len(message.data)
            if held > MAX_CHUNK_BYTES:
                raise ChunkTooLarge(
                    f"{self.path}: its chunks overlap in time so that more than "
                    f"{MAX_CHUNK_BYTES // (1024 * 1024)} MiB of messages would be held to give "
                    "them in order; refusing it"
                )
        while waiting:
            yield given()

    @staticmethod
    def _bag_message(channels: dict[int, Channel], message: Message) -> BagMessage:
        topic = channels[message.channel_id].topic
        return BagMessage(topic, message.data, message.log_time, message.publish_time)

    def close(self) -> None:
        self.stream.close()
