"""The recorder's account of what was lost before it received it (rosbag2/loss.py):
counted per topic, stored in metadata.yaml's custom_data, shown by `rosbag info`."""

from __future__ import annotations

from helpers import run
from rclpy.serialization import serialize_message
from std_msgs.msg import String

from rosbag2.loss import LOST_PREFIX, LossCount, lost_in
from rosbag2.metadata import TopicInfo
from rosbag2.writer import BagWriter


def test_sequence_gaps_count_while_the_topic_has_one_publisher():
    loss = LossCount()
    for sequence in (1, 2, 5, 6, 10):  # 3, 4 and 7-9 never came
        loss.received("/a", sequence)
    loss.look_at_publishers(lambda topic: 1)  # the first look: not yet known to be one
    assert loss.totals() == {}
    for sequence in (11, 15):
        loss.received("/a", sequence)
    loss.look_at_publishers(lambda topic: 1)
    assert loss.totals() == {"/a": 3}
    assert loss.news() == [("/a", 3, 3)]
    assert loss.news() == []  # told once


def test_a_batch_counts_as_its_messages_one_by_one():
    one_by_one, batched = LossCount(), LossCount()
    sequences = [1, 2, None, 5, 0, 6, 10, 3, 4]  # unknown numbers; a new publisher from 3
    for sequence in sequences:
        one_by_one.received("/a", sequence)
    batched.received_many("/a", sequences[:4])
    batched.received_many("/a", sequences[4:])
    for loss in (one_by_one, batched):
        loss.look_at_publishers(lambda topic: 1)
        loss.received_many("/a", [5, 7])
        loss.look_at_publishers(lambda topic: 1)
    assert one_by_one.totals() == batched.totals() == {"/a": 1}
    assert one_by_one.topics["/a"].last_sequence == batched.topics["/a"].last_sequence == 7


def test_two_publishers_numbers_are_not_gaps():
    loss = LossCount()
    loss.look_at_publishers(lambda topic: 2)
    for sequence in (1, 1, 2, 2, 3, 40, 4, 41):  # two publishers interleaved
        loss.received("/a", sequence)
    loss.look_at_publishers(lambda topic: 2)
    loss.look_at_publishers(lambda topic: 2)
    assert loss.totals() == {}


def test_the_middleware_count_and_the_gaps_are_two_witnesses_of_one_loss():
    loss = LossCount()
    loss.middleware_lost("/b", 7)
    loss.middleware_lost("/b", 4)  # a running total never goes back
    assert loss.totals() == {"/b": 7}
    assert loss.custom_data() == {LOST_PREFIX + "/b": "7"}
    assert lost_in(loss.custom_data()) == {"/b": 7}
    assert lost_in(["not", "a", "mapping"]) == {}
    assert lost_in({LOST_PREFIX + "/c": "many", "other": "1"}) == {}


def test_info_shows_what_a_recording_lost(tmp_path):
    folder = tmp_path / "lossy"
    loss = LossCount()
    loss.middleware_lost("/chatter", 12)
    writer = BagWriter(folder, custom_data=loss.custom_data())
    writer.add_topic(TopicInfo("/chatter", "std_msgs/msg/String"), "string data\n", "ros2msg")
    writer.write("/chatter", serialize_message(String(data="hi")), 1_700_000_000_000_000_000, 0)
    writer.close()
    ros2 = run("ros2", "bag", "info", str(folder))
    assert ros2.returncode == 0, ros2.stderr
    assert "Messages lost:     12 before the recorder received them (/chatter 12)" in ros2.stdout
    ros1 = run("rosbag", "info", str(folder))
    assert "lost:        12 before the recorder received them (/chatter 12)" in ros1.stdout
