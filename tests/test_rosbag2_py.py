"""rosbag2_py, rosbag2's Python API, as the official Jazzy page "Recording a bag from a node
(Python)" uses it: the page's package and its three programs, typed as printed
(tests/data/workspace/), built with the real colcon; what they write is read back by
`ros2 bag info`, `ros2 bag play` and the independent mcap reader. Then the reader's side of the
API (SequentialReader) and its errors."""

from __future__ import annotations

import sys
from itertools import pairwise
from pathlib import Path

import pytest
import yaml
from example_interfaces.msg import Int32
from helpers import TIMEOUT, spin_until
from mcap.reader import make_reader
from rclpy.node import Node
from rclpy.serialization import deserialize_message, serialize_message
from std_msgs.msg import String
from test_workspace import (
    DATA,
    add_entry_points,
    colcon_build,
    create,
    new_workspace,
    ok,
    sourced,
    terminal,
)

import rosbag2_py

PROGRAMS = ("simple_bag_recorder", "data_generator_node", "data_generator_executable")


def recorded(bag: Path) -> int:
    """The messages a bag's metadata.yaml counts so far (the writer rewrites it each second)."""
    try:
        metadata = yaml.safe_load((bag / "metadata.yaml").read_text())
        return int(metadata["rosbag2_bagfile_information"]["message_count"])
    except (OSError, yaml.YAMLError, KeyError, TypeError):
        return 0


def mcap_messages(bag: Path) -> list[tuple[str, int, bytes]]:
    """(topic, log time, bytes) of every message, read with the mcap package."""
    [path] = bag.glob("*.mcap")
    with open(path, "rb") as stream:
        return [
            (channel.topic, message.log_time, message.data)
            for _schema, channel, message in make_reader(stream).iter_messages()
        ]


@pytest.fixture
def bag_package(tmp_path: Path) -> Path:
    """The page's steps 1 to 5.3: the package, its three files and entry points, built."""
    workspace = new_workspace(tmp_path)
    create(
        workspace,
        "--build-type ament_python --license Apache-2.0 bag_recorder_nodes_py "
        "--dependencies rclpy rosbag2_py example_interfaces std_msgs",
    )
    package = workspace / "src" / "bag_recorder_nodes_py"
    assert "<depend>rosbag2_py</depend>" in (package / "package.xml").read_text()
    for name in PROGRAMS:
        (package / "bag_recorder_nodes_py" / f"{name}.py").write_text(
            (DATA / f"{name}.py").read_text()
        )
    add_entry_points(
        package / "setup.py",
        *(f"{name} = bag_recorder_nodes_py.{name}:main" for name in PROGRAMS),
    )
    colcon_build(workspace, "--packages-select bag_recorder_nodes_py")
    return workspace


@pytest.mark.long  # a colcon build, and the talker's messages at 1 Hz
def test_the_pages_nodes_write_bags_that_ros2_bag_reads_and_plays(
    bag_package, ros_domain, context, executor
):
    workspace = bag_package
    # --dependencies rosbag2_py: the package is in the ament index, as ROS 2's would be.
    assert ok(sourced("ros2 pkg prefix rosbag2_py"), workspace) == f"{sys.prefix}\n"
    # 5: the executable writes 100 Int32, 1 s apart in bag time, and ends.
    ok(sourced("ros2 run bag_recorder_nodes_py data_generator_executable"), workspace)
    info = ok(sourced("ros2 bag info big_synthetic_bag"), workspace)
    assert (
        "Topic: synthetic | Type: example_interfaces/msg/Int32 | Count: 100 | "
        "Serialization Format: cdr" in info
    ), info
    messages = mcap_messages(workspace / "big_synthetic_bag")
    assert [deserialize_message(m[2], Int32).data for m in messages] == list(range(100))
    assert {b[1] - a[1] for a, b in pairwise(messages)} == {10**9}

    # 3: the recorder and the talker, both stopped with Ctrl-C; then a listener and play.
    recorder = terminal(workspace, "ros2 run bag_recorder_nodes_py simple_bag_recorder")
    talker = terminal(workspace, "ros2 run demo_nodes_cpp talker")
    my_bag = workspace / "my_bag"
    try:
        spin_until(executor, lambda: recorded(my_bag) >= 3, what="3 messages in my_bag")
    finally:
        recorder.interrupt()
        talker.interrupt()
    count = len(mcap_messages(my_bag))  # the summary at the end: the writer was closed
    assert count == recorded(my_bag) >= 3
    info = ok(sourced("ros2 bag info my_bag"), workspace)
    assert f"Topic: chatter | Type: std_msgs/msg/String | Count: {count} |" in info, info
    listener = terminal(workspace, "ros2 run demo_nodes_cpp listener")
    node = Node("bag_page_check", context=context)
    executor.add_node(node)
    spin_until(executor, lambda: node.count_subscribers("/chatter") > 0, what="the listener")
    try:
        ok(sourced("ros2 bag play my_bag"), workspace, timeout=TIMEOUT + count)
        heard = listener.wait_for_text("I heard: [Hello World: ", count=count)
    finally:
        listener.kill()
    assert len([line for line in heard if "I heard: [Hello World: " in line]) == count

    # 4: the node with a timer, stopped with Ctrl-C after a few messages.
    generator = terminal(workspace, "ros2 run bag_recorder_nodes_py data_generator_node")
    timed = workspace / "timed_synthetic_bag"
    try:
        spin_until(executor, lambda: recorded(timed) >= 2, what="2 messages in the timed bag")
    finally:
        generator.interrupt()
    values = [deserialize_message(m[2], Int32).data for m in mcap_messages(timed)]
    assert values == list(range(len(values))) and len(values) >= 2


def test_the_reader_gives_back_what_the_writer_wrote(tmp_path):
    uri = str(tmp_path / "words")
    writer = rosbag2_py.SequentialWriter()
    writer.open(
        rosbag2_py.StorageOptions(uri=uri, storage_id="mcap"), rosbag2_py.ConverterOptions("", "")
    )
    for topic in ("/a", "/b"):
        writer.create_topic(
            rosbag2_py.TopicMetadata(
                id=0, name=topic, type="std_msgs/msg/String", serialization_format="cdr"
            )
        )
    sent = []
    for i in range(6):
        topic = "/a" if i % 2 == 0 else "/b"
        data = serialize_message(String(data=f"{topic} {i}"))
        writer.write(topic, data, 1_000 + i)
        sent.append((topic, data, 1_000 + i))
    writer.close()

    reader = rosbag2_py.SequentialReader()
    reader.open(
        rosbag2_py.StorageOptions(uri=uri, storage_id="mcap"), rosbag2_py.ConverterOptions("", "")
    )
    topics = reader.get_all_topics_and_types()
    assert [(t.name, t.type, t.serialization_format) for t in topics] == [
        ("/a", "std_msgs/msg/String", "cdr"),
        ("/b", "std_msgs/msg/String", "cdr"),
    ]
    read = []
    while reader.has_next():
        read.append(reader.read_next())
    assert read == sent
    with pytest.raises(RuntimeError, match="Bag is at end"):
        reader.read_next()
    reader.seek(1_003)
    reader.set_filter(rosbag2_py.StorageFilter(topics=["/b"]))
    assert [reader.read_next()[2] for _ in range(2)] == [1_003, 1_005]
    assert not reader.has_next()
    reader.reset_filter()
    reader.seek(0)
    assert reader.read_next() == sent[0]


def test_what_rosbag2_refuses_is_a_runtime_error(tmp_path):
    writer = rosbag2_py.SequentialWriter()
    with pytest.raises(RuntimeError, match=r"Bag is not open. Call open\(\) before writing."):
        writer.write("/a", b"", 0)
    options = rosbag2_py.StorageOptions(uri=str(tmp_path), storage_id="mcap")
    with pytest.raises(RuntimeError, match="Bag directory already exists"):
        writer.open(options, rosbag2_py.ConverterOptions("", ""))
    sqlite = rosbag2_py.StorageOptions(uri=str(tmp_path / "x"), storage_id="sqlite3")
    with pytest.raises(RuntimeError, match="storage id 'sqlite3'"):
        writer.open(sqlite, rosbag2_py.ConverterOptions("", ""))
    writer.open(rosbag2_py.StorageOptions(uri=str(tmp_path / "y")), rosbag2_py.ConverterOptions())
    with pytest.raises(RuntimeError, match="Call create_topic"):
        writer.write("/unknown", b"", 0)
    reader = rosbag2_py.SequentialReader()
    with pytest.raises(RuntimeError, match="does not exist"):
        reader.open_uri(str(tmp_path / "nothing"))
    # A reader whose second bag would not open is closed, not reading the first bag's file.
    reader.open_uri(str(tmp_path / "y"))
    with pytest.raises(RuntimeError, match="does not exist"):
        reader.open_uri(str(tmp_path / "nothing"))
    with pytest.raises(RuntimeError, match="Bag is not open"):
        reader.has_next()
