"""`rosbag info BAG` / `ros2 bag info BAG`: what a bag holds, from its summary.

Nothing scans the messages: each MCAP file's summary (statistics, channels, schemas) at its
end says how many messages of which topic, from when to when. `ros2 bag info` prints
`ros2 bag info`'s layout; `rosbag info` the fields of ROS 1's (seed 004): path, version,
duration, start, end, size, messages, compression, types, topics.
"""

from __future__ import annotations

import sys
import time

from ros_tutorials_common.names import SERVICE_EVENT_SUFFIX
from rosbag2.metadata import NS, TopicInfo
from rosbag2.reader import Bag, BagReader


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


def is_service_event_topic(name: str, type_name: str) -> bool:
    """rosbag2_cpp's test: the topic ends in /_service_event, the type is pkg/srv/Name_Event."""
    return (
        len(name) > len(SERVICE_EVENT_SUFFIX)
        and name.endswith(SERVICE_EVENT_SUFFIX)
        and "/srv/" in type_name
        and len(type_name) > len("_Event")
        and type_name.endswith("_Event")
    )


def service_name(event_topic: str) -> str:
    return event_topic[: -len(SERVICE_EVENT_SUFFIX)]


def service_type(event_type: str) -> str:
    return event_type[: -len("_Event")]


PAD = " " * 19  # rosbag2: the longest field name ("Topic information:") and a space


def ros2_info(bag: Bag, only_topics: bool = False) -> str:
    """The layout of ROS 2 Jazzy's `ros2 bag info` (rosbag2_py's format_bag_meta_data).

    Service event topics are counted apart: `Messages:` leaves them out, `Service:` lists them.
    """
    services = [t for t in bag.topics.values() if is_service_event_topic(t.name, t.type)]
    topics = [t for t in bag.topics.values() if t not in services]
    lines = [""]
    names = [path.name for path in bag.files]
    lines.append("Files:             " + f"\n{PAD}".join(names))
    lines.append(f"Bag size:          {file_size(bag.size)}")
    lines.append(f"Storage id:        {bag.storage_id}")
    lines.append(f"ROS Distro:        {bag.ros_distro or 'unknown'}")
    lines.append(f"Duration:          {_stamp(bag.duration)[2]}s")
    lines.append(f"Start:             {_time_point(bag.start)}")
    lines.append(f"End:               {_time_point(bag.end)}")
    event_count = sum(t.message_count for t in services)
    lines.append(f"Messages:          {bag.message_count - event_count}")
    if bag.lost:  # this project's: what the recording lost before it received it (loss.py)
        lines.append(f"Messages lost:     {_lost_text(bag.lost)}")
    topic_lines = [
        f"Topic: {t.name} | Type: {t.type} | Count: {t.message_count} | "
        f"Serialization Format: {t.serialization_format}"
        for t in topics
    ]
    lines.append("Topic information: " + f"\n{PAD}".join(topic_lines))
    if only_topics:
        return "\n".join(lines) + "\n"
    lines.append(f"Service:           {len(services)}")
    service_lines = [
        f"Service: {service_name(t.name)} | Type: {service_type(t.type)} | "
        f"Event Count: {t.message_count} | Serialization Format: {t.serialization_format}"
        for t in services
    ]
    text = "\n".join(lines) + "\nService information: "
    if service_lines:
        text += f"\n{PAD}  ".join(service_lines) + "\n"
    return text


def _lost_text(lost: dict[str, int]) -> str:
    per_topic = ", ".join(f"{topic} {count}" for topic, count in sorted(lost.items()))
    return f"{sum(lost.values())} before the recorder received them ({per_topic})"


def topic_names(bag: Bag) -> str:
    """`ros2 bag info -t`: the topics' names, service event topics left out."""
    return "\n".join(
        t.name for t in bag.topics.values() if not is_service_event_topic(t.name, t.type)
    )


def service_counts(reader: BagReader) -> list[tuple[TopicInfo, int, int]]:
    """Per service event topic: (topic, requests, responses), each counted once per client
    and sequence number however many events (sent, received) tell of it (rosbag2's
    Info::read_service_info)."""
    from rclpy.serialization import deserialize_message
    from service_msgs.msg import ServiceEventInfo

    services = {
        t.name: t for t in reader.bag.topics.values() if is_service_event_topic(t.name, t.type)
    }
    seen: dict[str, tuple[set, set]] = {name: (set(), set()) for name in services}
    for message in reader.messages(list(services)):
        # An event's CDR starts with its ServiceEventInfo, which reads on its own.
        info = deserialize_message(message.data, ServiceEventInfo)
        key = (bytes(info.client_gid), info.sequence_number)
        requests, responses = seen[message.topic]
        if info.event_type in (ServiceEventInfo.REQUEST_SENT, ServiceEventInfo.REQUEST_RECEIVED):
            requests.add(key)
        elif info.event_type in (
            ServiceEventInfo.RESPONSE_SENT,
            ServiceEventInfo.RESPONSE_RECEIVED,
        ):
            responses.add(key)
    return [(services[name], len(r), len(s)) for name, (r, s) in seen.items()]


def ros2_service_info(counts: list[tuple[TopicInfo, int, int]]) -> str:
    """`ros2 bag info -v`'s service part (rosbag2_py's format_service_info)."""
    head = "Service information: "
    lines = [
        f"Service: {service_name(t.name)} | Type: {service_type(t.type)} | "
        f"Request Count: {requests} | Response Count: {responses} | "
        f"Serialization Format: {t.serialization_format}"
        for t, requests, responses in counts
    ]
    text = f"Service:           {len(counts)}\n{head}"
    if lines:
        text += f"\n{' ' * len(head)}".join(lines) + "\n"
    return text


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
    if bag.lost:
        lines.append(f"lost:        {_lost_text(bag.lost)}")
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
    # Printed as ros2bag prints it: print() of a text that ends in a line break already.
    print(ros1_info(bag) if ros1 else ros2_info(bag))


def print_ros2_info(path: str, topic_name: bool, verbose: bool) -> None:
    """`ros2 bag info BAG [-t] [-v]`."""
    if topic_name and verbose:
        print(
            "Warning! You have set both the '-t' and '-v' parameters. The '-t' parameter "
            "will be ignored."
        )
    with BagReader(path) as reader:
        bag = reader.bag
        counts = service_counts(reader) if verbose else []
    for warning in bag.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    if verbose:
        print(ros2_info(bag, only_topics=True) + ros2_service_info(counts))
    elif topic_name:
        names = topic_names(bag)
        if names:
            print(names)
    else:
        print(ros2_info(bag))
