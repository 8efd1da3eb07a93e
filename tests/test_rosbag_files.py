"""rosbag / ros2 bag with files that are not what they should be, and ROS 2's own bags.

Bags written by ROS 2's rosbag2 itself (tests/data/ros2_bags) open and play here; a type
not installed here is a warning for its topic. Every bad input ends with one clear line and
a non-zero exit status, never a traceback: a missing path, a folder without metadata, a
foreign or truncated file, an existing output name, a full disk (a real small tmpfs, and a
write-failing file in a unit test), invalid rates and durations. A recorder killed with
SIGKILL leaves a bag that is readable up to its last flush.
"""

from __future__ import annotations

import errno
import os
import re
import select
import shutil
import signal
import subprocess
import termios
import time
import warnings
from pathlib import Path

import pytest
import yaml
from helpers import BIN, TIMEOUT, NodeProcess, run, spin_until
from mcap.reader import make_reader
from rclpy.node import Node
from rclpy.qos import QoSProfile
from rclpy.serialization import serialize_message
from rosbags.rosbag2 import Reader
from std_msgs.msg import String

from ros2cmd.errors import ToolError
from rosbag2 import definitions, offered_qos
from rosbag2 import writer as bag_writer
from rosbag2.errors import BagError
from rosbag2.metadata import FileInfo, TopicInfo, bag_metadata, dump_yaml, metadata_text
from rosbag2.reader import BagReader
from rosbag2.writer import BagWriter

ROS2_BAGS = Path(__file__).parent / "data" / "ros2_bags"


def fails(*args: str) -> str:
    """A command that must fail with one error line (exit 1), no traceback."""
    result = run(*args)
    assert result.returncode == 1, f"{' '.join(args)}: {result.returncode}\n{result.stdout}"
    assert "Traceback" not in result.stderr
    lines = [line for line in result.stderr.splitlines() if not line.startswith("warning:")]
    assert len(lines) == 1, f"expected one error line, got:\n{result.stderr}"
    assert lines[0].startswith("error: ")
    return lines[0]


def usage_error(*args: str) -> str:
    result = run(*args)
    assert result.returncode == 2, f"{' '.join(args)}: {result.returncode}\n{result.stderr}"
    assert "usage:" in result.stderr and "Traceback" not in result.stderr
    return result.stderr.strip().splitlines()[-1]


def write_bag(
    folder: Path, topics: dict[str, str], count: int = 5, spacing: float = 0.1
) -> list[bytes]:
    """A small bag written directly (no ROS graph): `count` String messages per topic."""
    writer = BagWriter(folder, chunk_size=500)  # several chunks, even for a few messages
    sent = []
    for topic, type_name in topics.items():
        writer.add_topic(TopicInfo(topic, type_name), "string data\n", "ros2msg")
    for i in range(count):
        for topic in topics:
            data = serialize_message(String(data=f"{topic} {i}"))
            sent.append(data)
            writer.write(topic, data, 1_700_000_000_000_000_000 + int(i * spacing * 1e9), 0)
    writer.close()
    return sent


@pytest.fixture
def small_bag(tmp_path: Path) -> Path:
    folder = tmp_path / "small"
    write_bag(folder, {"/words": "std_msgs/msg/String"}, count=50)
    return folder


# ROS 2's own bags


def test_a_bag_written_by_ros2_plays_here(ros_domain, context, executor) -> None:
    bag = ROS2_BAGS / "talker"
    with open(bag / "talker.mcap", "rb") as stream:
        recorded = [
            m.data for _s, c, m in make_reader(stream).iter_messages() if c.topic == "/topic"
        ]
    result = run("ros2", "bag", "info", str(bag))
    assert result.returncode == 0, result.stderr
    assert "Topic: /topic | Type: std_msgs/msg/String | Count: 10 | Serialization Format: cdr" in (
        result.stdout
    )
    node = Node("ros2_bag_check", context=context)
    executor.add_node(node)
    received: list[bytes] = []
    node.create_subscription(String, "/topic", lambda data: received.append(data), 100, raw=True)
    player = NodeProcess(
        str(BIN / "rosbag"), "play", str(bag), "--topics", "/topic", "-r", "5",
        "--wait-for-subscribers", "--timeout", "30",
    )  # fmt: skip
    spin_until(executor, lambda: len(received) >= len(recorded), what="the ROS 2 bag played")
    assert player.wait() == 0, player.output
    assert received == recorded


def test_types_not_installed_are_a_warning_per_topic(ros_domain, tmp_path) -> None:
    # rosbag2's own bag: every type in it (test_msgs, rosbag2_interfaces) is unknown here.
    bag = ROS2_BAGS / "bag_with_topics_and_service_events"
    info = run("rosbag", "info", str(bag))
    assert info.returncode == 0 and "messages:    10" in info.stdout, info.stderr
    error = fails("rosbag", "play", str(bag))
    assert "no topic to play" in error
    # A bag with one unknown type and one known: the known one plays, exit 0.
    folder = tmp_path / "mixed"
    write_bag(folder, {"/known": "std_msgs/msg/String", "/unknown": "no_such_msgs/msg/Thing"})
    result = run("rosbag", "play", str(folder), "-r", "10")
    assert result.returncode == 0, result.stderr
    warnings = [line for line in result.stderr.splitlines() if line.startswith("warning:")]
    assert len(warnings) == 1 and "/unknown" in warnings[0] and "no_such_msgs" in warnings[0]
    assert "Done: 5 messages published." in result.stdout


# Bad input


def test_missing_foreign_and_metadata_less_bags_are_refused(tmp_path, small_bag) -> None:
    assert "does not exist" in fails("rosbag", "info", str(tmp_path / "nothing"))
    assert "does not exist" in fails("rosbag", "play", str(tmp_path / "nothing"))
    bare = tmp_path / "bare"
    bare.mkdir()
    shutil.copy(small_bag / "small_0.mcap", bare)
    error = fails("ros2", "bag", "info", str(bare))
    assert "has no metadata.yaml" in error and "small_0.mcap" in error  # names the way out
    # ... whose MCAP file alone still opens
    assert run("ros2", "bag", "info", str(bare / "small_0.mcap")).returncode == 0
    assert "not a bag folder" in fails("rosbag", "reindex", str(bare / "small_0.mcap"))
    assert "does not exist" in fails("ros2", "bag", "reindex", str(tmp_path / "nothing"))
    foreign = tmp_path / "notes.mcap"
    foreign.write_text("these are not the bytes you are looking for\n" * 10)
    assert "is not an MCAP file" in fails("rosbag", "info", str(foreign))
    assert "is not an MCAP file" in fails("rosbag", "play", str(foreign))
    not_metadata = tmp_path / "odd"
    not_metadata.mkdir()
    (not_metadata / "metadata.yaml").write_text("just: some yaml\n")
    assert "is not rosbag2 metadata" in fails("rosbag", "info", str(not_metadata))
    (not_metadata / "metadata.yaml").write_text("{{{ not yaml")
    assert "cannot read" in fails("rosbag", "info", str(not_metadata))
    sqlite = tmp_path / "sqlite"
    sqlite.mkdir()
    (sqlite / "metadata.yaml").write_text(
        "rosbag2_bagfile_information:\n  storage_identifier: sqlite3\n"
    )
    assert "uses storage 'sqlite3'" in fails("rosbag", "info", str(sqlite))


def test_truncated_files(tmp_path, small_bag) -> None:
    mcap_file = small_bag / "small_0.mcap"
    whole = mcap_file.read_bytes()
    # Cut within the data: the summary is gone; what is complete is still read, with a warning.
    folder = tmp_path / "cut"
    shutil.copytree(small_bag, folder)
    (folder / "small_0.mcap").write_bytes(whole[: len(whole) // 2])
    with BagReader(folder) as reader:
        assert not reader.bag.complete
        kept = list(reader.messages())
    assert 0 < len(kept) < 50
    result = run("rosbag", "info", str(folder))
    assert result.returncode == 0 and "Traceback" not in result.stderr
    assert "has no summary" in result.stderr and f"messages:    {len(kept)}" in result.stdout
    # Cut to almost nothing: not an MCAP file any more.
    (folder / "small_0.mcap").write_bytes(whole[:10])
    assert "is not an MCAP file" in fails("rosbag", "info", str(folder))


def test_info_reads_the_summary_not_the_messages(tmp_path, small_bag) -> None:
    """Damage every message's bytes: info still answers from the summary at the end."""
    folder = tmp_path / "damaged"
    shutil.copytree(small_bag, folder)
    path = folder / "small_0.mcap"
    data = bytearray(path.read_bytes())
    for index in range(len(data)):
        if data[index : index + 7] == b"/words ":  # the messages' text, in the chunk
            data[index : index + 7] = b"XXXXXXX"
    path.write_bytes(bytes(data))
    result = run("ros2", "bag", "info", str(folder))
    assert result.returncode == 0, result.stderr
    assert "Messages:          50" in result.stdout
    # Reading the messages does notice (the chunk's CRC): one clear line.
    assert "damaged" in fails("rosbag", "play", str(folder))


def test_an_existing_output_is_never_overwritten(ros_domain, tmp_path) -> None:
    existing = tmp_path / "existing"
    existing.mkdir()
    (existing / "keep.txt").write_text("mine")
    assert "already exists" in fails("rosbag", "record", "/chatter", "-O", str(existing))
    # ros2 bag's own line (ros2bag's validate_parsed_arguments), exit 1.
    result = run("ros2", "bag", "record", "/chatter", "-o", str(existing))
    assert result.returncode == 1
    assert result.stderr == f"[ERROR] [ros2bag]: Output folder '{existing}' already exists.\n"
    assert [p.name for p in existing.iterdir()] == ["keep.txt"]
    with pytest.raises(BagError, match="already exists"):
        BagWriter(existing)


@pytest.mark.parametrize(
    "args",
    [
        ("rosbag", "play", "BAG", "-r", "0"),
        ("rosbag", "play", "BAG", "--rate", "-2"),
        ("ros2", "bag", "play", "BAG", "--rate", "abc"),
        ("ros2", "bag", "play", "BAG", "--rate", "nan"),
        ("rosbag", "play", "BAG", "--start-offset", "-1"),
        ("rosbag", "record", "/chatter", "--duration", "0"),
        ("rosbag", "record", "/chatter", "--duration", "-5"),
        ("rosbag", "record", "/chatter", "--duration", "soon"),
        ("ros2", "bag", "record", "/chatter", "--max-messages", "0"),
    ],
)
def test_invalid_rates_and_durations_are_usage_errors(args, small_bag) -> None:
    args = tuple(str(small_bag) if arg == "BAG" else arg for arg in args)
    assert "error:" in usage_error(*args)


def test_other_bad_requests_are_one_line(ros_domain, small_bag) -> None:
    assert "beyond the bag's end" in fails("rosbag", "play", str(small_bag), "--start-offset", "60")
    assert "expected FROM:=TO" in fails("rosbag", "play", str(small_bag), "--remap", "/a=/b")
    assert "-a" in fails("rosbag", "record")
    assert "not both" in fails("rosbag", "record", "-a", "/chatter")


def test_a_full_disk_stops_the_write_and_keeps_what_was_written(tmp_path, monkeypatch) -> None:
    """Unit test: the .mcap file's writes fail with ENOSPC after 20 kB."""
    real_write = bag_writer._File.write

    def write(self, data):
        if self.offset + len(data) > 20_000:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return real_write(self, data)

    monkeypatch.setattr(bag_writer._File, "write", write)
    writer = BagWriter(tmp_path / "full", chunk_size=2_000, flush_period=3600)
    writer.add_topic(TopicInfo("/words", "std_msgs/msg/String"), "string data\n", "ros2msg")
    with pytest.raises(BagError, match="No space left on device") as failure:
        for i in range(10_000):
            writer.write("/words", b"\x00\x01\x00\x00" + bytes(100), i, 0)
    writer.close()  # safe after a failure
    assert "stay readable" in str(failure.value)
    with BagReader(tmp_path / "full") as reader:
        assert not reader.bag.complete
        messages = list(reader.messages())
    assert 50 < len(messages) < 10_000
    assert [m.log_time for m in messages] == list(range(len(messages)))


def test_a_full_disk_while_recording(ros_domain, tmp_path) -> None:
    """A real full file system: a 1 MiB tmpfs in a private mount namespace (unshare)."""
    if shutil.which("unshare") is None:
        pytest.skip("unshare is not installed")
    probe = subprocess.run(
        ["unshare", "-rm", "sh", "-c", f"mount -t tmpfs -o size=64k tmpfs {tmp_path}"],
        capture_output=True,
    )
    if probe.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {probe.stderr.decode().strip()}")
    disk, out = tmp_path / "disk", tmp_path / "out"
    disk.mkdir()
    out.mkdir()
    publisher = NodeProcess(
        str(BIN / "ros2"), "topic", "pub", "/big", "std_msgs/msg/String",
        "{data: " + "x" * 8000 + "}", "-r", "50",
    )  # fmt: skip
    try:
        script = (
            f"mount -t tmpfs -o size=1m tmpfs {disk} || exit 99; "
            f"{BIN / 'rosbag'} record /big -O {disk}/bag; status=$?; "
            f"cp -a {disk}/bag {out}/bag; exit $status"
        )
        result = subprocess.run(
            ["unshare", "-rm", "sh", "-c", script], capture_output=True, text=True, timeout=120
        )
    finally:
        publisher.kill()
    assert result.returncode == 1, result.stdout + result.stderr
    errors = [line for line in result.stderr.splitlines() if line.startswith("error:")]
    assert len(errors) == 1 and "No space left on device" in errors[0], result.stderr
    assert "Traceback" not in result.stderr
    with BagReader(out / "bag") as reader:
        messages = list(reader.messages())
    assert len(messages) > 0
    assert all(len(m.data) > 8000 for m in messages)


def test_sigkill_leaves_a_bag_readable_up_to_the_last_flush(ros_domain, tmp_path) -> None:
    folder = tmp_path / "killed"
    talker = NodeProcess("-m", "ros_tutorials_topic.talker")
    recorder = NodeProcess(str(BIN / "rosbag"), "record", "/chatter", "-O", str(folder))
    try:
        recorder.wait_for_output(
            lambda lines: any("Subscribed to topic '/chatter'" in line for line in lines),
            what="recorder subscribed",
        )

        def flushed_count() -> int:
            try:
                text = (folder / "metadata.yaml").read_text()
            except OSError:
                return 0
            return yaml.safe_load(text)["rosbag2_bagfile_information"]["message_count"]

        deadline = time.monotonic() + 60
        while flushed_count() < 5:  # metadata.yaml follows every flush (once a second)
            assert time.monotonic() < deadline, "no flush within 60 s"
            time.sleep(0.1)
        at_kill = flushed_count()
        os.killpg(recorder.process.pid, signal.SIGKILL)
        recorder.process.wait()
    finally:
        recorder.kill()
        talker.kill()
    result = run("rosbag", "info", str(folder))
    assert result.returncode == 0, result.stderr
    assert "has no summary" in result.stderr
    with BagReader(folder) as reader:
        messages = list(reader.messages())
    assert len(messages) >= at_kill
    assert all(m.topic == "/chatter" for m in messages)
    # `rosbag reindex` gives it its summary: readers that need one (rosbags) open it then.
    result = run("rosbag", "reindex", str(folder))
    assert result.returncode == 0, result.stderr
    with Reader(folder) as independent:
        raw = [data for _connection, _time, data in independent.messages()]
    assert raw == [m.data for m in messages]
    metadata = yaml.safe_load((folder / "metadata.yaml").read_text())
    assert metadata["rosbag2_bagfile_information"]["message_count"] == len(messages)


def test_space_pauses_and_s_steps_in_a_terminal(ros_domain, tmp_path) -> None:
    folder = tmp_path / "steps"
    write_bag(folder, {"/words": "std_msgs/msg/String"}, count=20, spacing=1.0)  # 19 s long
    controller, terminal = os.openpty()
    saved = termios.tcgetattr(terminal)
    player = subprocess.Popen(
        [str(BIN / "rosbag"), "play", str(folder)],
        stdin=terminal,
        stdout=terminal,
        stderr=terminal,
        start_new_session=True,
    )
    text = ""

    def wait_for(pattern: str, count: int = 1) -> str:
        nonlocal text
        deadline = time.monotonic() + TIMEOUT
        while len(re.findall(pattern, text)) < count:
            assert time.monotonic() < deadline, f"{pattern!r} not seen; output:\n{text}"
            ready, _, _ = select.select([controller], [], [], 0.5)
            if ready:
                text += os.read(controller, 4096).decode(errors="replace")
        return text

    try:
        wait_for("Hit space to toggle paused, or 's' to step.")
        os.write(controller, b" ")
        wait_for(r"\[PAUSED\]")
        for steps in (1, 2, 3):
            os.write(controller, b"s")
            wait_for(r"\[PAUSED\]", 1 + steps)
        bag_times = [float(t) for t in re.findall(r"\[PAUSED\]  Bag Time: ([\d.]+)", text)]
        assert bag_times[1:] == sorted(set(bag_times[1:])), text  # one message further each
        os.write(controller, b" ")
        wait_for(r"\[RUNNING\]")
        player.send_signal(signal.SIGINT)
        assert player.wait(TIMEOUT) == 130  # interrupted before its end
        # The terminal is left as it was found (echo and line mode back).
        assert termios.tcgetattr(terminal) == saved
    finally:
        if player.poll() is None:
            player.kill()
            player.wait()
        os.close(controller)
        os.close(terminal)


# The format's details


def test_definitions_follow_rosbag2() -> None:
    text = definitions.message_definition("ros_tutorials_interfaces/msg/MsgTutorial")
    time_msg = definitions.definition_path("builtin_interfaces", "msg", "Time").read_text()
    tutorial_msg = definitions.definition_path(
        "ros_tutorials_interfaces", "msg", "MsgTutorial"
    ).read_text()
    assert text == tutorial_msg + "\n" + "=" * 80 + "\nMSG: builtin_interfaces/Time\n" + time_msg
    image = definitions.message_definition("sensor_msgs/msg/Image")
    assert image.count("MSG: std_msgs/Header\n") == 1
    assert image.count("MSG: builtin_interfaces/Time\n") == 1  # once, though nested
    with pytest.raises(ToolError, match="no definition file"):
        definitions.message_definition("no_such_msgs/msg/Thing")


def test_qos_of_every_metadata_version_reads_as_names() -> None:
    old = "- history: 3\n  depth: 0\n  reliability: 2\n  durability: 1\n"
    assert offered_qos.qos_profiles_from_yaml(old)[0]["reliability"] == "best_effort"
    assert offered_qos.qos_profiles_from_yaml(old)[0]["durability"] == "transient_local"
    new = [{"history": "keep_last", "reliability": "reliable", "durability": "volatile"}]
    assert offered_qos.qos_profiles_from_yaml(new)[0]["reliability"] == "reliable"
    assert offered_qos.qos_profiles_from_yaml("") == []


def _with_metadata(tmp_path: Path, small_bag: Path, change) -> Path:
    """A copy of small_bag whose metadata.yaml change() rewrote."""
    folder = tmp_path / f"bag{len(list(tmp_path.iterdir()))}"
    shutil.copytree(small_bag, folder)
    path = folder / "metadata.yaml"
    path.write_text(change(path.read_text()))
    return folder


def test_metadata_of_the_wrong_shape_or_size_is_refused(tmp_path, small_bag) -> None:
    """metadata.yaml is input like any other: an int where a list goes, a 5,000-character
    file name, a 20,000-deep list, a 200 MB file gave tracebacks, a RecursionError, 651 MB."""
    inner = "rosbag2_bagfile_information:\n  storage_identifier: mcap\n"
    cases = {
        "topics_with_message_count is not a list": lambda text: re.sub(
            r"topics_with_message_count:.*?(\n  \w)",
            r"topics_with_message_count: 7\1",
            text,
            flags=re.S,
        ),
        "not a file of the bag's folder": lambda text: text.replace(
            "- small_0.mcap", "- " + "x" * 5000
        ),
        "nested more than": lambda text: (
            inner + "  relative_file_paths: " + "[" * 20000 + "]" * 20000
        ),
        "larger than": lambda text: inner + "  custom: '" + "x" * (20 * 1024 * 1024) + "'\n",
    }
    for expected, change in cases.items():
        folder = _with_metadata(tmp_path, small_bag, change)
        assert expected in fails("rosbag", "info", str(folder)), expected
    assert expected in fails("ros2", "bag", "play", str(folder))


def test_metadata_text_is_the_yaml_dump_with_no_anchors() -> None:
    """metadata.yaml's text, each topic rendered once (the recorder rewrites it every second),
    is what dump_yaml writes; a QoS list shared by every topic is written out each time, as
    yaml-cpp does, not as a YAML anchor and aliases."""
    shared_qos = [offered_qos.qos_to_dict(QoSProfile(depth=10))]
    topics = [
        TopicInfo(f"/t{i}", "std_msgs/msg/String", shared_qos, "RIHS01_ab", message_count=i)
        for i in range(3)
    ] + [TopicInfo("/quiet", "std_msgs/msg/String")]
    for custom_data in (None, {"lost": "7"}):
        data = bag_metadata(topics, [FileInfo("b_0.mcap", 5, 10, 3)], "jazzy", custom_data)
        text = metadata_text(data)
        assert text == dump_yaml({"rosbag2_bagfile_information": data})
        assert "&id" not in text and "*id" not in text
        assert yaml.safe_load(text) == {"rosbag2_bagfile_information": data}
    assert metadata_text(bag_metadata([], [FileInfo("b_0.mcap")])) == dump_yaml(
        {"rosbag2_bagfile_information": bag_metadata([], [FileInfo("b_0.mcap")])}
    )


def test_a_batch_of_messages_is_written_as_one_at_a_time(tmp_path) -> None:
    """write_many (the recorder's batches): every message, in order, counted per topic, the
    bag's start and duration from the earliest and latest receive times, chunks in between."""
    writer = BagWriter(tmp_path / "batch", chunk_size=1_000, flush_period=3600)
    for topic in ("/a", "/b"):
        writer.add_topic(TopicInfo(topic, "std_msgs/msg/String"), "string data\n", "ros2msg")
    data = b"\x00\x01\x00\x00" + bytes(60)
    writer.write_many("/a", [(data, 100 + i, i) for i in range(300)])
    writer.write_many("/b", [(data, 50, 0), (data, 900, 1)])  # earlier and later than /a's
    writer.write_many("/b", [])
    writer.write("/a", data, 400, 300)
    assert writer.topics["/a"].message_count == 301 and writer.topics["/b"].message_count == 2
    assert (writer.file_info.starting_time, writer.file_info.duration) == (50, 850)
    assert writer.message_count == 303
    writer.close()
    with BagReader(tmp_path / "batch") as reader:
        assert reader.bag.topics["/a"].message_count == 301
        assert (reader.bag.start, reader.bag.end) == (50, 900)
        assert reader.bag.chunk_count > 3
        messages = list(reader.messages())
    assert sorted(m.log_time for m in messages if m.topic == "/a") == list(range(100, 401))


def test_overlapping_chunks_are_read_in_log_time_order_from_the_start(tmp_path) -> None:
    """A file whose chunks overlap in time (not what this recorder writes; another writer's)
    is read merged in log-time order, from the start offset on, with no warning."""
    from mcap.writer import Writer

    from rosbag2.mcap_file import McapFile

    path = tmp_path / "overlap.mcap"
    with open(path, "wb") as stream:
        writer = Writer(stream, chunk_size=1)  # one message per chunk
        writer.start(profile="ros2", library="test")
        schema = writer.register_schema("std_msgs/msg/String", "ros2msg", b"string data")
        channel = writer.register_channel("/chatter", "cdr", schema)
        for log_time in (10, 30, 20, 40):  # chunk [30] and chunk [20] overlap
            data = serialize_message(String(data=str(log_time)))
            writer.add_message(channel, log_time, data, log_time)
        writer.finish()
    bag = McapFile(path)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # the mcap reader's deprecated arguments included
            times = [message.log_time for message in bag.messages(None, start=20)]
    finally:
        bag.close()
    assert times == [20, 30, 40]


def test_chunks_overlapping_without_end_are_refused_not_held(tmp_path, monkeypatch) -> None:
    """Chunks that each span the whole bag (a crafted file can claim it) would keep every
    message waiting to be put in order: refused once what waits passes the chunk limit."""
    from mcap.writer import Writer

    from rosbag2 import mcap_file

    path = tmp_path / "spans.mcap"
    with open(path, "wb") as stream:
        writer = Writer(stream, chunk_size=60)  # two messages a chunk
        writer.start(profile="ros2", library="test")
        schema = writer.register_schema("std_msgs/msg/String", "ros2msg", b"string data")
        channel = writer.register_channel("/chatter", "cdr", schema)
        for k in range(1, 51):  # chunk k holds log times k and 101 - k: all of them overlap
            for log_time in (k, 101 - k):
                data = serialize_message(String(data="x"))
                writer.add_message(channel, log_time, data, log_time)
        writer.finish()
    bag = mcap_file.McapFile(path)
    try:
        assert len(list(bag.messages(None))) == 100  # under the limit: all, in order
        monkeypatch.setattr(mcap_file, "MAX_CHUNK_BYTES", 200)  # 50 wait, 10 bytes each
        with pytest.raises(mcap_file.BagError, match="chunks overlap in time so that more than"):
            list(bag.messages(None))
    finally:
        bag.close()


# Crafted files: a chunk's declared size is checked before it is decompressed

MCAP_MAGIC = b"\x89MCAP0\r\n"


def _zstd_zeros(mib: int) -> bytes:
    """`mib` MiB of zeros as one zstd frame that does not declare its size (about 32 bytes per
    MiB: what makes a decompression bomb of a small file)."""
    import zstandard

    compressor = zstandard.ZstdCompressor(level=1).compressobj()
    zeros = bytes(1 << 20)
    return b"".join([compressor.compress(zeros) for _ in range(mib)] + [compressor.flush()])


def _one_chunk_mcap(path: Path, compression: str, data: bytes, declared: int) -> None:
    """An MCAP file without a summary (as a killed recording leaves): a /chatter channel and
    one chunk holding `data`, which says it decompresses to `declared` bytes."""
    from mcap.data_stream import RecordBuilder
    from mcap.records import Channel, Chunk, DataEnd, Footer, Header, Schema

    builder = RecordBuilder()
    Header(profile="ros2", library="test").write(builder)
    Schema(id=1, name="std_msgs/msg/String", encoding="ros2msg", data=b"string data").write(builder)
    Channel(id=1, schema_id=1, topic="/chatter", message_encoding="cdr", metadata={}).write(builder)
    Chunk(
        compression=compression,
        data=data,
        message_start_time=0,
        message_end_time=1,
        uncompressed_crc=0,
        uncompressed_size=declared,
    ).write(builder)
    DataEnd(data_section_crc=0).write(builder)
    Footer(summary_start=0, summary_offset_start=0, summary_crc=0).write(builder)
    path.write_bytes(MCAP_MAGIC + builder.end() + MCAP_MAGIC)


def _under_memory_cap(*args: str, cap: int = 1 << 30) -> subprocess.CompletedProcess:
    """A console script run with at most `cap` bytes of address space (started cold: the
    limit must hold from its start)."""
    import resource

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (cap, cap))

    return subprocess.run(
        [str(BIN / args[0]), *args[1:]],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
        preexec_fn=limit,
    )


def test_a_decompression_bomb_is_refused_under_a_memory_cap(ros_domain, tmp_path, small_bag):
    """2 GiB of zeros in a 64 KB chunk: its declared size is refused before anything is
    decompressed, by info, play and reindex alike, within 1 GiB of address space (mcap's own
    reader allocated the declared size: a MemoryError under the cap, gigabytes without)."""
    from rosbag2.mcap_file import MAX_CHUNK_BYTES

    declared = 2048 << 20
    assert declared > MAX_CHUNK_BYTES
    folder = tmp_path / "bomb"
    shutil.copytree(small_bag, folder)
    mcap_file = folder / "small_0.mcap"
    _one_chunk_mcap(mcap_file, "zstd", _zstd_zeros(2048), declared)
    assert mcap_file.stat().st_size < 100_000
    expected = (
        f"error: {mcap_file}: a chunk declares {declared} bytes uncompressed, more than the "
        f"{MAX_CHUNK_BYTES >> 20} MiB a chunk may have here; refusing it\n"
    )
    for command in (
        ("ros2", "bag", "info", str(folder)),
        ("ros2", "bag", "play", str(folder)),
        ("ros2", "bag", "reindex", str(folder)),
        ("rosbag", "info", str(mcap_file)),
    ):
        result = _under_memory_cap(*command)
        assert (result.returncode, result.stderr) == (1, expected), command
    assert mcap_file.stat().st_size < 100_000  # reindex left it as it was


def _patch_chunk_size(path: Path, size: int) -> None:
    """Make the first chunk of a complete file declare `size` bytes uncompressed."""
    import struct

    with open(path, "rb") as stream:
        summary = make_reader(stream).get_summary()
    assert summary is not None
    offset = summary.chunk_indexes[0].chunk_start_offset + 1 + 8 + 16  # opcode, length, times
    data = bytearray(path.read_bytes())
    data[offset : offset + 8] = struct.pack("<Q", size)
    path.write_bytes(bytes(data))


def test_a_chunk_that_decompresses_to_another_size_is_damaged(ros_domain, tmp_path):
    """A chunk whose data decompresses to more (or less) than it declares is read no further
    than the declared size: one line naming the file; and one declaring too much is refused
    when played from a complete file too."""
    from mcap.writer import CompressionType, Writer

    path = tmp_path / "lz4.mcap"
    with open(path, "wb") as stream:
        writer = Writer(stream, compression=CompressionType.LZ4)
        writer.start(profile="ros2", library="test")
        schema = writer.register_schema("std_msgs/msg/String", "ros2msg", b"string data")
        channel = writer.register_channel("/chatter", "cdr", schema)
        writer.add_message(channel, 1, serialize_message(String(data="x" * 100_000)), 1)
        writer.finish()
    whole = path.read_bytes()
    for declared, what in ((100, "more"), (10**6, "bytes")):
        path.write_bytes(whole)
        _patch_chunk_size(path, declared)
        error = fails("rosbag", "play", str(path))
        assert error.startswith(f"error: {path} is damaged: a chunk decompresses to ")
        assert f"{what}, not the {declared} bytes it declares" in error
    path.write_bytes(whole)
    _patch_chunk_size(path, 2**40)
    assert f"a chunk declares {2**40} bytes uncompressed" in fails("rosbag", "play", str(path))


def test_a_bag_name_too_long_for_its_file_is_refused_and_nothing_is_left(ros_domain, tmp_path):
    """A bag's file adds `_0.mcap` to the folder's name: a name of 249 to 255 bytes makes a
    folder that can be created and a file that cannot. One line before anything is made."""
    name = "d" * 250
    for command in (
        ("ros2", "bag", "record", "-o", name, "/chatter"),
        ("rosbag", "record", "-O", name, "/chatter"),
    ):
        result = run(*command, cwd=str(tmp_path))
        assert result.returncode == 1, result.stderr
        assert "Traceback" not in result.stderr
        lines = result.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith("error: cannot create "), lines
        assert "(with '_0.mcap') would be 257 bytes, more than the 255" in lines[0]
        assert list(tmp_path.iterdir()) == []


def _many_channels_mcap(path: Path, channels: int, messages: int = 20) -> None:
    """One schema, CHANNELS channel records (ids wrapping at 65,536 as MCAP's uint16 does, a
    topic each), MESSAGES messages; no chunks and no summary, as a killed recording ends:
    written record by record with the mcap library."""
    from mcap.data_stream import RecordBuilder
    from mcap.records import Channel, Header, Message, Schema

    builder = RecordBuilder()
    Header(profile="ros2", library="test").write(builder)
    Schema(id=1, name="std_msgs/msg/String", encoding="ros2msg", data=b"string data").write(builder)
    for number in range(channels):
        Channel(
            id=number % 65536, schema_id=1, topic=f"/t{number}", message_encoding="cdr", metadata={}
        ).write(builder)
    data = serialize_message(String(data="x"))
    for number in range(messages):
        Message(
            channel_id=number % channels,
            sequence=number,
            log_time=10**9 + number * 10**7,
            publish_time=10**9,
            data=data,
        ).write(builder)
    path.write_bytes(MCAP_MAGIC + builder.end())


def test_a_bag_declaring_100000_channels_is_refused_in_one_line(ros_domain, tmp_path):
    """3.5 MB declaring 100,000 channels: refused by info and play alike, within 1 GiB of
    address space (play made a publisher for each, 25 MB a second, silent, for minutes)."""
    from rosbag2.mcap_file import MAX_CHANNELS

    path = tmp_path / "channels.mcap"
    _many_channels_mcap(path, 100_000)
    expected = (
        f"error: {path} declares more than {MAX_CHANNELS} channels; a bag here may declare "
        f"at most {MAX_CHANNELS}: refusing it\n"
    )
    for command in (
        ("ros2", "bag", "play", str(path)),
        ("ros2", "bag", "info", str(path)),
        ("rosbag", "play", str(path)),
    ):
        result = _under_memory_cap(*command)
        assert (result.returncode, result.stderr) == (1, expected), command


def test_a_channel_id_declared_twice_as_two_topics_is_damage(tmp_path, monkeypatch):
    from rosbag2 import mcap_file

    monkeypatch.setattr(mcap_file, "MAX_CHANNELS", 70_000)
    path = tmp_path / "twice.mcap"
    _many_channels_mcap(path, 65537)  # id 0: /t0, then /t65536
    twice = "is damaged: channel id 0 is declared twice, as '/t0' and as '/t65536'"
    with pytest.raises(BagError, match=twice):
        BagReader(path)


def test_play_makes_at_most_max_publishers(ros_domain, tmp_path):
    """More topics to play than MAX_PUBLISHERS: one line, nothing made; chosen with
    --topics, the bag plays."""
    from ros2cmd.bag.play import MAX_PUBLISHERS

    path = tmp_path / "topics.mcap"
    _many_channels_mcap(path, MAX_PUBLISHERS + 1)
    expected = (
        f"{path}: {MAX_PUBLISHERS + 1} topics to play; play makes at most {MAX_PUBLISHERS} "
        "publishers: choose topics with --topics"
    )
    assert fails("ros2", "bag", "play", str(path)) == f"error: {expected}"
    assert fails("rosbag", "play", str(path)) == f"error: {expected}"
    result = run("ros2", "bag", "play", str(path), "--topics", "/t1", "/t2")
    assert result.returncode == 0 and "Traceback" not in result.stderr, result.stderr


def test_sigterm_while_play_makes_its_publishers_ends_it(ros_domain, tmp_path):
    """As many topics as play makes publishers for: SIGTERM on the way ends play at once,
    without a traceback (each made publisher is closed, not left to rclpy's exit)."""
    from ros2cmd.bag.play import MAX_PUBLISHERS

    path = tmp_path / "topics.mcap"
    _many_channels_mcap(path, MAX_PUBLISHERS)
    play = NodeProcess(str(BIN / "ros2"), "bag", "play", str(path))
    play.wait_for_text("has no summary")  # printed just before the publishers are made
    play.process.send_signal(signal.SIGTERM)
    code = play.wait()
    assert "Traceback" not in play.output and code in (0, 130), (code, play.output)
