"""rosbag2_py: rosbag2's Python API (ROS 2 Jazzy) for reading and writing bags from your own
code, as the official tutorial "Recording a bag from a node (Python)" uses it.

rosbag2_py is not on PyPI; this is its API over this project's bag library (rosbag2/: the
writer and reader `ros2 bag` uses too), so a bag written here is what `ros2 bag record` writes
(mcap storage) and `ros2 bag play` and `ros2 bag info` read it. What is here: SequentialWriter
(open, create_topic, write, close), SequentialReader (open, open_uri, has_next, read_next,
get_all_topics_and_types, set_filter, reset_filter, seek), and in ``rosbag2_py._storage``
StorageOptions, ConverterOptions, TopicMetadata and StorageFilter. Not here: compression,
the Player and Recorder classes, bag splitting; `ros2 bag` does what they do.
"""

from rosbag2_py._reader import SequentialReader
from rosbag2_py._storage import (
    ConverterOptions,
    StorageFilter,
    StorageOptions,
    TopicMetadata,
    get_default_storage_id,
)
from rosbag2_py._writer import SequentialWriter

__all__ = [
    "ConverterOptions",
    "SequentialReader",
    "SequentialWriter",
    "StorageFilter",
    "StorageOptions",
    "TopicMetadata",
    "get_default_storage_id",
]
