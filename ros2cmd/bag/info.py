"""`rosbag info BAG` / `ros2 bag info BAG`: what a bag holds, from its summary.

Nothing scans the messages: each MCAP file's summary (statistics, channels, schemas) at its
end says how many messages of which topic, from when to when. `ros2 bag info` prints
`ros2 bag info`'s layout; `rosbag info` the fields of ROS 1's (seed 004): path, version,
duration, start, end, size, messages, compression, types, topics.
"""

from __future__ import annotations

import sys
import time

from ros2cmd.bag.storage import NS, Bag, BagReader


def _stamp(nanoseconds: int) -> tuple[str, str, str]:
    """(date, time with nanoseconds, seconds.nanoseconds) in local time, as ros2 bag info."""
    seconds, fraction = divmod(nanoseconds, NS)
    local = time.localtime(seconds)
    date = time.strftime("%b ", local) + f"{local.tm_mday:>2}" + time.strftime(" %Y", local)
    return date, time.strftime("%H:%M:%S", local) + f".{fraction:09d}", f"{seconds}.{fraction:09d}"


def _time_point(nanoseconds: int) -> str:
    date, clock, seconds = _stamp(nanoseconds)
    return f"{date} {clock} ({seconds})"


def file_size(size: float, units: tuple[str, ...] = ("B", "KiB", "MiB", "GiB", "TiB")) -> str:
    index = 0
    while size >= 1024 and index < len(units) - 1:
        size /= 1024
        index += 1
    return f"{size:.{0 if index == 0 else 1}f} {units[index]}"


def ros2_info(bag: Bag) -> str:
    """The layout of ROS 2 Jazzy's `ros2 bag info`."""
    pad = " " * 19
    lines = [""]
    names = [path.name for path in bag.files]
    lines.append("Files:             " + f"\n{pad}".join(names))
    lines.append(f"Bag size:          {file_size(bag.size)}")
    lines.append(f"Storage id:        {bag.storage_id}")
    lines.append(f"ROS Distro:        {bag.ros_distro or 'unknown'}")
    lines.append(f"Duration:          {_stamp(bag.duration)[2]}s")
    lines.append(f"Start:             {_time_point(bag.start)}")
    lines.append(f"End:               {_time_point(bag.end)}")
    lines.append(f"Messages:          {bag.message_count}")
    topics = [
        f"Topic: {t.name} | Type: {t.type} | Count: {t.message_count} | "
        f"Serialization Format: {t.serialization_format}"
        for t in bag.topics.values()
    ]
    lines.append("Topic information: " + f"\n{pad}".join(topics))
    lines.append("Service:           0")
    lines.append("Service information: ")
    return "\n".join(lines)


def ros1_info(bag: Bag) -> str:
    """The fields of ROS 1's `rosbag info` (seed 004), with ROS 2's names and hashes."""
    pad = " " * 13
    duration = bag.duration / NS
    lines = [
        f"path:        {bag.path}",
        f"version:     rosbag2 (metadata {bag.version or 'none'}), {bag.storage_id} storage",
        f"duration:    {duration:.1f}s",
        f"start:       {_ros1_time(bag.start)}",
        f"end:         {_ros1_time(bag.end)}",
        f"size:        {file_size(bag.size, ('B', 'KB', 'MB', 'GB', 'TB'))}",
        f"messages:    {bag.message_count}",
        f"compression: none [{bag.chunk_count}/{bag.chunk_count} chunks]",
    ]
    types: dict[str, str] = {}
    for topic in bag.topics.values():
        types.setdefault(topic.type, topic.type_description_hash)
    type_width = max((len(t) for t in types), default=0)
    type_lines = [f"{name:<{type_width}} [{h}]" if h else name for name, h in sorted(types.items())]
    lines.append("types:       " + f"\n{pad}".join(type_lines))
    topics = sorted(bag.topics.values(), key=lambda t: t.name)
    name_width = max((len(t.name) for t in topics), default=0)
    count_width = max((len(str(t.message_count)) for t in topics), default=0)
    topic_lines = [
        f"{t.name:<{name_width}}  {t.message_count:>{count_width}} msgs : {t.type}" for t in topics
    ]
    lines.append("topics:      " + f"\n{pad}".join(topic_lines))
    return "\n".join(lines)


def _ros1_time(nanoseconds: int) -> str:
    seconds, fraction = divmod(nanoseconds, NS)
    local = time.localtime(seconds)
    hundredths = fraction // 10_000_000
    text = time.strftime("%b %d %Y %H:%M:%S", local)
    return f"{text}.{hundredths:02d} ({seconds}.{hundredths:02d})"


def print_info(path: str, ros1: bool = False) -> None:
    with BagReader(path) as reader:
        bag = reader.bag
    for warning in bag.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    print(ros1_info(bag) if ros1 else ros2_info(bag))
