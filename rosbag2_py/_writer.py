"""rosbag2_py._writer: SequentialWriter, rosbag2's Python writer (Jazzy), on this project's bag
writer (rosbag2/writer.py): the folder, .mcap file and metadata.yaml `ros2 bag record`
writes, which `ros2 bag play` and `ros2 bag info` read.

As with the real bindings, a writer that is never closed is closed when it is garbage
collected or when Python exits (the official tutorial's nodes end with Ctrl-C and never call
close())."""

from __future__ import annotations

import weakref
from collections.abc import Callable
from pathlib import Path

from ros_tutorials_common.errors import ToolError
from rosbag2.definitions import schema
from rosbag2.errors import BagError
from rosbag2.metadata import TopicInfo
from rosbag2.offered_qos import qos_to_dict
from rosbag2.writer import BagWriter
from rosbag2_py._storage import ConverterOptions, StorageOptions, TopicMetadata, check_options


class SequentialWriter:
    """Writes messages into a bag in the order they are given."""

    def __init__(self) -> None:
        self._writer: BagWriter | None = None
        self._close = None

    def open(
        self, storage_options: StorageOptions, converter_options: ConverterOptions | None = None
    ) -> None:
        check_options(storage_options.storage_id, converter_options)
        folder = Path(storage_options.uri)
        if folder.is_dir():
            raise RuntimeError(
                f"Bag directory already exists ({folder}), can't overwrite existing bag"
            )
        self.close()
        try:
            writer = BagWriter(folder, custom_data=storage_options.custom_data or None)
        except BagError as error:
            raise RuntimeError(str(error)) from None
        self._writer = writer
        self._close = weakref.finalize(self, writer.close)

    def create_topic(self, topic: TopicMetadata) -> None:
        writer = self._open_writer("creating a topic")
        try:
            definition, encoding = schema(topic.type)
        except (ToolError, ValueError):
            definition, encoding = "", "unknown"  # as rosbag2 leaves a type it cannot find
        profiles = [
            qos if isinstance(qos, dict) else qos_to_dict(qos) for qos in topic.offered_qos_profiles
        ]
        info = TopicInfo(
            name=topic.name,
            type=topic.type,
            offered_qos_profiles=profiles,
            type_description_hash=topic.type_description_hash,
            serialization_format=topic.serialization_format or "cdr",
        )
        self._guard(writer.add_topic, info, definition, encoding)

    def write(
        self,
        topic_name: str,
        message: bytes,
        recv_timestamp: int,
        send_timestamp: int | None = None,
    ) -> None:
        """One serialized message (``rclpy.serialization.serialize_message``), with its
        receive time and optionally its send time, in nanoseconds."""
        writer = self._open_writer("writing")
        if topic_name not in writer.channels:
            raise RuntimeError(
                f"Failed to write on topic '{topic_name}'. Call create_topic() before first write."
            )
        send = recv_timestamp if send_timestamp is None else send_timestamp
        self._guard(writer.write, topic_name, bytes(message), int(recv_timestamp), int(send))

    def close(self) -> None:
        """Finish the bag (its summary and metadata.yaml); the writer can open another."""
        if self._close is not None:
            self._close()
        self._writer = self._close = None

    def _open_writer(self, what: str) -> BagWriter:
        if self._writer is None:
            raise RuntimeError(f"Bag is not open. Call open() before {what}.")
        return self._writer

    @staticmethod
    def _guard(function: Callable[..., object], *args: object) -> None:
        try:
            function(*args)
        except BagError as error:
            raise RuntimeError(str(error)) from None
