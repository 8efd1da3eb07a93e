"""rosbag / ros2 bag: record real lesson nodes, read the bag independently, play it back.

The topic lesson's publisher and the parameter lesson's talker run as processes; `rosbag
record` (the installed console script) records them. The bag is read back with `rosbags`,
a reader written independently of this project, and with the `mcap` package, and every
message is compared with what the publisher logged it sent. `rosbag play` publishes the bag
into a subscriber here, which compares bytes, order and spacing.
"""

from __future__ import annotations

import re
import signal
import time
from pathlib import Path

import pytest
import yaml
from helpers import BIN, TIMEOUT, NodeProcess, run, spin_until
from mcap.reader import make_reader
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from rclpy.serialization import deserialize_message
from ros_tutorials_interfaces.msg import MsgTutorial
from rosbags.rosbag2 import Reader
from rosbags.typesys import Stores, get_types_from_msg, get_typestore
from std_msgs.msg import String

TALKER_TEXT = "recorded by the bag test"


def rosbag(*args: str) -> NodeProcess:
    """`rosbag ...` as a real process (the installed console script)."""
    return NodeProcess(str(BIN / "rosbag"), *args)


def wait_subscribed(recorder: NodeProcess, *topics: str) -> None:
    for topic in topics:
        recorder.wait_for_output(
            lambda lines, t=topic: any(f"Subscribed to topic '{t}'" in line for line in lines),
            what=f"recorder subscribed to {topic}",
        )


def sent_messages(publisher: NodeProcess) -> list[tuple[int, int, int]]:
    """(sec, nanosec, data) of every message the topic lesson's publisher logged."""
    numbers = [int(n) for n in re.findall(r"send msg = (-?\d+)", publisher.output)]
    return [tuple(numbers[i : i + 3]) for i in range(0, len(numbers) - 2, 3)]


def read_with_rosbags(folder: Path) -> tuple[int, list[tuple[str, int, bytes, object]]]:
    """Every message as (topic, log time, raw bytes, decoded) through the rosbags package."""
    typestore = get_typestore(Stores.ROS2_JAZZY)
    messages = []
    with Reader(folder) as reader:
        types = {}
        for connection in reader.connections:
            if connection.msgtype not in typestore.types:  # ours: from the bag's own schema
                types.update(get_types_from_msg(connection.msgdef.data, connection.msgtype))
        typestore.register(types)
        for connection, timestamp, raw in reader.messages():
            decoded = typestore.deserialize_cdr(raw, connection.msgtype)
            messages.append((connection.topic, timestamp, raw, decoded))
        count = reader.message_count
    return count, messages


@pytest.fixture(scope="module")
def lesson_bag(ros_domain: int, tmp_path_factory: pytest.TempPathFactory):
    """A bag of the topic lesson and the parameter lesson's talker, recorded for real."""
    folder = tmp_path_factory.mktemp("bags") / "lessons"
    processes = [
        NodeProcess("-m", "ros_tutorials_topic.publisher"),
        NodeProcess(
            "-m", "ros_tutorials_parameter.talker", "--ros-args", "-p", f"talker_str:={TALKER_TEXT}"
        ),
    ]
    publisher, talker = processes
    recorder = rosbag("record", "/ros_tutorial_msg", "/chatter", "-O", str(folder))
    processes.append(recorder)
    try:
        wait_subscribed(recorder, "/ros_tutorial_msg", "/chatter")
        # Let it record a few seconds of both (10 Hz each), then Ctrl-C as a user would.
        sent, said = len(sent_messages(publisher)), talker.output.count(TALKER_TEXT)
        publisher.wait_for_output(
            lambda _lines: len(sent_messages(publisher)) >= sent + 25, timeout=60, what="25 sends"
        )
        talker.wait_for_output(
            lambda _lines: talker.output.count(TALKER_TEXT) >= said + 25, timeout=60, what="25 says"
        )
        assert recorder.interrupt() == 0, recorder.output
        for process in processes:  # nothing live on these topics while the bag plays
            process.kill()
        yield folder, publisher, recorder
    finally:
        for process in processes:
            process.kill()


def test_record_prints_what_it_records_and_the_summary(lesson_bag) -> None:
    folder, _publisher, recorder = lesson_bag
    output = recorder.output
    assert f"Recording to '{folder}'" in output
    assert "Recording stopped (SIGINT received)" in output
    assert "Traceback" not in output
    # The summary printed at the end is rosbag info's (the seed's fields).
    for field in ("path:", "duration:", "start:", "end:", "size:", "messages:", "types:"):
        assert field in output
    assert re.search(
        r"/ros_tutorial_msg\s+\d+ msgs : ros_tutorials_interfaces/msg/MsgTutorial", output
    )


def test_every_recorded_message_is_one_the_publisher_sent(lesson_bag) -> None:
    folder, publisher, _recorder = lesson_bag
    count, messages = read_with_rosbags(folder)
    sent = sent_messages(publisher)
    tutorial = [m for m in messages if m[0] == "/ros_tutorial_msg"]
    chatter = [m for m in messages if m[0] == "/chatter"]
    assert len(tutorial) >= 10 and len(chatter) >= 10
    assert len(messages) == count == len(tutorial) + len(chatter)
    recorded = [(m[3].stamp.sec, m[3].stamp.nanosec, m[3].data) for m in tutorial]
    # Every message, in order, without a gap: a contiguous run of what was sent.
    first = sent.index(recorded[0])
    assert recorded == sent[first : first + len(recorded)]
    for _topic, _time, raw, decoded in chatter:
        assert decoded.data == TALKER_TEXT
        # The bytes are what rclpy itself deserializes to the same message.
        assert deserialize_message(raw, String).data == TALKER_TEXT
    for _topic, _time, raw, decoded in tutorial:
        msg = deserialize_message(raw, MsgTutorial)
        assert (msg.stamp.sec, msg.stamp.nanosec, msg.data) == (
            decoded.stamp.sec,
            decoded.stamp.nanosec,
            decoded.data,
        )
    times = [m[1] for m in messages]
    assert times == sorted(times)


def test_the_bag_is_rosbag2_mcap_as_ros2_jazzy_writes_it(lesson_bag) -> None:
    folder, _publisher, _recorder = lesson_bag
    metadata = yaml.safe_load((folder / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
    assert metadata["version"] == 9
    assert metadata["storage_identifier"] == "mcap"
    assert metadata["relative_file_paths"] == [f"{folder.name}_0.mcap"]
    assert metadata["ros_distro"] == "jazzy"
    topics = {t["topic_metadata"]["name"]: t for t in metadata["topics_with_message_count"]}
    assert set(topics) == {"/ros_tutorial_msg", "/chatter"}
    chatter = topics["/chatter"]["topic_metadata"]
    assert chatter["type"] == "std_msgs/msg/String"
    assert chatter["serialization_format"] == "cdr"
    assert chatter["type_description_hash"].startswith("RIHS01_")
    assert chatter["offered_qos_profiles"][0]["reliability"] == "reliable"
    assert metadata["message_count"] == sum(t["message_count"] for t in topics.values())
    assert metadata["files"][0]["message_count"] == metadata["message_count"]

    # The MCAP file, read with the reference implementation, CRCs checked.
    with open(folder / f"{folder.name}_0.mcap", "rb") as stream:
        reader = make_reader(stream, validate_crcs=True)
        assert reader.get_header().profile == "ros2"
        summary = reader.get_summary()
        assert summary is not None and summary.statistics.message_count == metadata["message_count"]
        schemas = {s.name: s for s in summary.schemas.values()}
        assert schemas["std_msgs/msg/String"].encoding == "ros2msg"
        tutorial_schema = schemas["ros_tutorials_interfaces/msg/MsgTutorial"].data.decode()
        # The definition with its dependency, separated as rosbag2 separates them.
        assert tutorial_schema.startswith("builtin_interfaces/Time stamp\nint32 data\n")
        assert "\n" + "=" * 80 + "\nMSG: builtin_interfaces/Time\n" in tutorial_schema
        for channel in summary.channels.values():
            assert channel.message_encoding == "cdr"
            qos = yaml.safe_load(channel.metadata["offered_qos_profiles"])
            assert qos[0]["durability"] == "volatile"
            assert channel.metadata["topic_type_hash"].startswith("RIHS01_")
        rosbag2_records = [m for m in reader.iter_metadata() if m.name == "rosbag2"]
        assert rosbag2_records, "rosbag2's metadata record is missing"
        count = sum(1 for _ in reader.iter_messages())
        assert count == metadata["message_count"]


def test_info_reads_the_seed_fields(lesson_bag) -> None:
    folder, _publisher, _recorder = lesson_bag
    _count, messages = read_with_rosbags(folder)
    counts = {t: sum(1 for m in messages if m[0] == t) for t in ("/chatter", "/ros_tutorial_msg")}
    result = run("rosbag", "info", str(folder))
    assert result.returncode == 0, result.stderr
    text = result.stdout
    assert f"path:        {folder}" in text
    assert f"messages:    {len(messages)}" in text
    assert "lost:" not in text  # one publisher per topic on a quiet graph: no false loss
    start = messages[0][1]
    assert f"({start // 10**9}." in text.split("start:")[1].splitlines()[0]
    assert re.search(rf"/chatter\s+{counts['/chatter']} msgs : std_msgs/msg/String", text)
    assert "types:       ros_tutorials_interfaces/msg/MsgTutorial [RIHS01_" in text or (
        "std_msgs/msg/String [RIHS01_" in text
    )
    result = run("ros2", "bag", "info", str(folder))
    assert result.returncode == 0, result.stderr
    text = result.stdout
    assert f"Files:             {folder.name}_0.mcap" in text
    assert "Storage id:        mcap" in text
    assert "ROS Distro:        jazzy" in text
    assert f"Messages:          {len(messages)}" in text
    assert (
        f"Topic: /ros_tutorial_msg | Type: ros_tutorials_interfaces/msg/MsgTutorial | "
        f"Count: {counts['/ros_tutorial_msg']} | Serialization Format: cdr"
    ) in text
    duration = (messages[-1][1] - messages[0][1]) / 1e9
    shown = float(re.search(r"Duration:\s+([\d.]+)s", text).group(1))
    assert abs(shown - duration) < 1e-6


class _Collector:
    """A raw subscription that keeps (bytes, arrival time) of each message."""

    def __init__(self, node: Node, msg_type: type, topic: str, qos: QoSProfile | int = 100):
        self.received: list[tuple[bytes, float]] = []
        node.create_subscription(
            msg_type,
            topic,
            lambda data: self.received.append((data, time.monotonic())),
            qos,
            raw=True,
        )


def test_play_publishes_the_same_bytes_in_order_with_the_recorded_spacing(
    lesson_bag, context, executor
) -> None:
    folder, _publisher, _recorder = lesson_bag
    _count, messages = read_with_rosbags(folder)
    node = Node("bag_play_check", context=context)
    executor.add_node(node)
    tutorial = _Collector(node, MsgTutorial, "/ros_tutorial_msg")
    chatter = _Collector(node, String, "/chatter")
    player = rosbag("play", str(folder), "--wait-for-subscribers", "--timeout", "30")
    expected = {
        "/ros_tutorial_msg": [m for m in messages if m[0] == "/ros_tutorial_msg"],
        "/chatter": [m for m in messages if m[0] == "/chatter"],
    }
    spin_until(
        executor,
        lambda: (
            len(tutorial.received) >= len(expected["/ros_tutorial_msg"])
            and len(chatter.received) >= len(expected["/chatter"])
        ),
        timeout=60,
        what="every message played back",
    )
    assert player.wait() == 0, player.output
    assert f"Opening {folder}" in player.output
    for topic, collector in (("/ros_tutorial_msg", tutorial), ("/chatter", chatter)):
        assert [data for data, _ in collector.received] == [m[2] for m in expected[topic]]
    # Spacing: the recorded 10 Hz, not a burst. A player is never early, so the span played
    # is at least the recorded one less a late first message; only a generous bound.
    recorded_span = (
        expected["/ros_tutorial_msg"][-1][1] - expected["/ros_tutorial_msg"][0][1]
    ) / 1e9
    played_span = tutorial.received[-1][1] - tutorial.received[0][1]
    assert played_span > 0.5 * recorded_span, (played_span, recorded_span)


def test_play_topics_remap_offset_and_rate(lesson_bag, context, executor) -> None:
    folder, _publisher, _recorder = lesson_bag
    _count, messages = read_with_rosbags(folder)
    start = messages[0][1]
    expected = [m[2] for m in messages if m[0] == "/chatter" and m[1] >= start + 10**9]
    node = Node("bag_remap_check", context=context)
    executor.add_node(node)
    renamed = _Collector(node, String, "/chatter_again")
    original = _Collector(node, MsgTutorial, "/ros_tutorial_msg")
    player = rostool_play = NodeProcess(
        str(BIN / "ros2"), "bag", "play", str(folder),
        "--topics", "/chatter",
        "--remap", "/chatter:=/chatter_again",
        "--start-offset", "1",
        "--rate", "4",
        "--wait-for-subscribers", "--timeout", "30",
    )  # fmt: skip
    spin_until(
        executor,
        lambda: len(renamed.received) >= len(expected),
        timeout=60,
        what="the remapped chatter played back",
    )
    assert rostool_play.wait() == 0, player.output
    assert [data for data, _ in renamed.received] == expected
    assert original.received == []  # not among --topics


def test_record_all_picks_up_later_topics_and_latched_messages(
    ros_domain, tmp_path, context, executor
) -> None:
    folder = tmp_path / "later"
    node = Node("bag_latch_source", context=context)
    executor.add_node(node)
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    publisher = node.create_publisher(String, "/latched_before", latched)
    publisher.publish(String(data="sent before the recorder started"))
    recorder = rosbag("record", "-a", "-o", str(folder))
    try:
        wait_subscribed(recorder, "/latched_before")
        talker = NodeProcess(
            "-m", "ros_tutorials_topic.talker", "--ros-args", "-r", "chatter:=/appeared_later"
        )
        try:
            wait_subscribed(recorder, "/appeared_later")
        finally:
            talker.kill()
        recorder.process.send_signal(signal.SIGTERM)  # SIGTERM too closes the bag properly
        assert recorder.wait() == 0, recorder.output
    finally:
        recorder.kill()
    _count, messages = read_with_rosbags(folder)
    latched_messages = [m for m in messages if m[0] == "/latched_before"]
    assert [m[3].data for m in latched_messages] == ["sent before the recorder started"]
    metadata = yaml.safe_load((folder / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
    qos = {
        t["topic_metadata"]["name"]: t["topic_metadata"]["offered_qos_profiles"]
        for t in metadata["topics_with_message_count"]
    }
    assert qos["/latched_before"][0]["durability"] == "transient_local"
    assert "/appeared_later" in qos

    # Played back, the topic is offered as recorded: transient local, so latched again.
    node.destroy_publisher(publisher)
    player = rosbag("play", str(folder), "--topics", "/latched_before", "/appeared_later", "--loop")
    try:
        player.wait_for_output(lambda lines: any("done." in line for line in lines), what="ready")
        late = _Collector(node, String, "/latched_before", latched)
        spin_until(executor, lambda: late.received, what="the latched message played back")
        assert deserialize_message(late.received[0][0], String).data == (
            "sent before the recorder started"
        )
        offered = node.get_publishers_info_by_topic("/latched_before")
        assert [p.qos_profile.durability for p in offered] == [DurabilityPolicy.TRANSIENT_LOCAL]
    finally:
        assert player.interrupt() == 0  # --loop runs until Ctrl-C: its normal end


def test_seed_004_steps_as_printed(ros_domain, tmp_path) -> None:
    """`rosbag record TOPIC`, Ctrl-C, `rosbag info BAG`, `rosbag play BAG`, in a fresh folder."""

    def in_folder(*argv: str) -> NodeProcess:  # the command, run from tmp_path
        code = (
            f"import os, sys; os.chdir({str(tmp_path)!r}); sys.argv = {['rosbag', *argv]!r}; "
            "from ros2cmd.ros1.rosbag import rosbag; sys.exit(rosbag())"
        )
        return NodeProcess("-c", code)

    publisher = NodeProcess("-m", "ros_tutorials_topic.publisher")
    recorder = in_folder("record", "/ros_tutorial_msg")
    try:
        wait_subscribed(recorder, "/ros_tutorial_msg")
        seen = len(sent_messages(publisher))
        publisher.wait_for_output(
            lambda _lines: len(sent_messages(publisher)) >= seen + 10, what="10 more sends"
        )
        assert recorder.interrupt() == 0, recorder.output
    finally:
        publisher.kill()
        recorder.kill()
    name = re.search(r"Recording to '(rosbag2_[\d_-]+)'", recorder.output).group(1)
    assert (tmp_path / name / "metadata.yaml").is_file()
    info = in_folder("info", name)
    assert info.wait() == 0
    assert re.search(
        r"/ros_tutorial_msg\s+\d+ msgs : ros_tutorials_interfaces/msg/MsgTutorial", info.output
    )
    _count, messages = read_with_rosbags(tmp_path / name)
    recorded = {m[3].data for m in messages}

    subscriber = NodeProcess("-m", "ros_tutorials_topic.subscriber")
    player = None
    try:
        deadline = time.monotonic() + TIMEOUT
        heard: set[int] = set()
        # As printed: no option. The player waits 0.2 s after advertising, which discovery
        # may outlast on a loaded machine, so play again until the subscriber heard some.
        while len(heard) < 3:
            assert time.monotonic() < deadline, subscriber.output
            player = in_folder("play", name)
            assert player.wait() == 0, player.output
            heard = {int(n) for n in re.findall(r"recieve msg = (-?\d+)", subscriber.output)}
            heard &= recorded
        assert f"Opening {name}" in player.output
        assert "Waiting 0.2 seconds after advertising topics... done." in player.output
    finally:
        subscriber.kill()
