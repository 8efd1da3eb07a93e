"""Repair (`rosbag reindex`, `ros2 bag reindex`): a summary for every .mcap file of a bag whose
recording did not finish, and an up-to-date metadata.yaml."""

from __future__ import annotations

import contextlib
import os
from pathlib import Path

from mcap.writer import CompressionType, Writer

from rosbag2.errors import BagError
from rosbag2.mcap_file import CHUNK_SIZE, LIBRARY, PROFILE, McapFile
from rosbag2.metadata import FileInfo, bag_metadata, write_metadata_file
from rosbag2.reader import Bag, BagReader


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


def _rewrite_with_summary(mcap_file: McapFile) -> None:
    temporary = mcap_file.path.with_name(mcap_file.path.name + ".reindex")
    try:
        with open(temporary, "wb") as stream:
            writer = Writer(stream, chunk_size=CHUNK_SIZE, compression=CompressionType.NONE)
            writer.start(profile=mcap_file.profile or PROFILE, library=LIBRARY)
            schema_ids: dict[int, int] = {}
            channel_ids: dict[int, int] = {}
            for channel, message in mcap_file.scan():
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
