"""rosbag2_py._reader: SequentialReader, rosbag2's Python reader (Jazzy), on this project's bag
reader (rosbag2/reader.py): a bag folder (or one .mcap file) of any writer, its messages
in time order."""

from __future__ import annotations

import re
import weakref
from collections.abc import Iterator

from rosbag2.errors import BagError
from rosbag2.mcap_file import BagMessage
from rosbag2.reader import BagReader
from rosbag2_py._storage import (
    ConverterOptions,
    StorageFilter,
    StorageOptions,
    TopicMetadata,
    check_options,
)


class SequentialReader:
    """Reads a bag's messages one at a time, in the order they were received."""

    def __init__(self) -> None:
        self._reader: BagReader | None = None
        self._close = None
        self._filter = StorageFilter()
        self._messages: Iterator[BagMessage] = iter(())
        self._next: BagMessage | None = None

    def open(
        self, storage_options: StorageOptions, converter_options: ConverterOptions | None = None
    ) -> None:
        check_options(storage_options.storage_id, converter_options)
        self.open_uri(storage_options.uri)

    def open_uri(self, uri: str) -> None:
        if self._close is not None:
            self._close()
            self._reader = self._close = self._next = None  # closed, until a bag opens
        try:
            reader = BagReader(uri)
        except BagError as error:
            raise RuntimeError(str(error)) from None
        self._reader = reader
        self._close = weakref.finalize(self, reader.close)
        self._restart(0)

    def has_next(self) -> bool:
        self._bag()
        return self._next is not None

    def read_next(self) -> tuple[str, bytes, int]:
        """(topic name, serialized message, receive time in ns) of the next message."""
        self._bag()
        if self._next is None:
            raise RuntimeError("Bag is at end. No next message.")
        message = self._next
        self._advance()
        return message.topic, message.data, message.log_time

    def get_all_topics_and_types(self) -> list[TopicMetadata]:
        return [
            TopicMetadata(
                id=index,
                name=topic.name,
                type=topic.type,
                serialization_format=topic.serialization_format,
                offered_qos_profiles=list(topic.offered_qos_profiles),
                type_description_hash=topic.type_description_hash,
            )
            for index, topic in enumerate(self._bag().bag.topics.values())
        ]

    def set_filter(self, storage_filter: StorageFilter) -> None:
        self._filter = storage_filter
        self._restart(self._next.log_time if self._next is not None else self._end())

    def reset_filter(self) -> None:
        self.set_filter(StorageFilter())

    def seek(self, timestamp: int) -> None:
        """Go to the first message received at or after timestamp (ns)."""
        self._restart(timestamp)

    def _bag(self) -> BagReader:
        if self._reader is None:
            raise RuntimeError("Bag is not open. Call open() before reading.")
        return self._reader

    def _end(self) -> int:
        return self._bag().bag.end + 1

    def _restart(self, timestamp: int) -> None:
        topics = [name for name in self._bag().bag.topics if self._wanted(name)]
        self._messages = self._bag().messages(topics, timestamp)
        self._advance()

    def _advance(self) -> None:
        try:
            self._next = next(self._messages)
        except StopIteration:
            self._next = None
        except BagError as error:
            raise RuntimeError(str(error)) from None

    def _wanted(self, name: str) -> bool:
        wanted = self._filter
        chosen = [*wanted.topics, *wanted.services_events]
        if chosen or wanted.regex:
            by_name = name in chosen
            by_regex = bool(wanted.regex) and re.fullmatch(wanted.regex, name) is not None
            if not (by_name or by_regex):
                return False
        if name in [*wanted.exclude_topics, *wanted.exclude_service_events]:
            return False
        return not (wanted.regex_to_exclude and re.fullmatch(wanted.regex_to_exclude, name))
