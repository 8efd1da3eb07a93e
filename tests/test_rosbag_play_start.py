"""`rosbag play` / `ros2 bag play` with a subscriber already waiting: every message reaches it.

The player's publishers are new; until discovery has matched them with the running
subscribers, what they publish goes to no one. Where the graph shows subscribers of the bag's
topics, play waits (bounded) until each publisher is matched, then starts the bag's clock. The
busy processes of tests/cpu_load.py make discovery slow, as on a loaded machine, and the
listener is stopped (SIGSTOP) while the player starts, as a process the scheduler left
waiting: it answers the player's discovery only after that.
"""

from __future__ import annotations

import os
import signal
import time

import pytest
from cpu_load import CpuLoad
from helpers import BIN, TIMEOUT, NodeProcess
from test_rosbag_files import write_bag

COUNT = 32
DESCHEDULED = 2.0  # seconds the listener stays stopped after the player started
# A listener in a process of its own, as a learner's in another terminal: one line a message.
LISTENER = """
import rclpy
from rclpy.node import Node
from std_msgs.msg import String
rclpy.init()
node = Node("bag_listener")
node.create_subscription(String, "/waiting_words", lambda m: print(m.data, flush=True), 100)
print("ready", flush=True)
try:
    rclpy.spin(node)
except BaseException:
    pass
"""


@pytest.mark.parametrize("spelling", [("rosbag", "play"), ("ros2", "bag", "play")])
def test_a_waiting_subscriber_receives_every_message_under_load(
    spelling, ros_domain, tmp_path, node_process
) -> None:
    folder = tmp_path / "words"
    write_bag(folder, {"/waiting_words": "std_msgs/msg/String"}, count=COUNT, spacing=0.01)
    listener = node_process("-c", LISTENER)
    listener.wait_for_text("ready")
    load = CpuLoad(2 * (os.cpu_count() or 1), nice=0, limit=TIMEOUT * 2)
    load.start()
    os.kill(listener.process.pid, signal.SIGSTOP)
    try:
        player = NodeProcess(str(BIN / spelling[0]), *spelling[1:], str(folder))
        time.sleep(DESCHEDULED)  # the fault itself: a stop of this length, not a wait
        os.kill(listener.process.pid, signal.SIGCONT)
        assert player.wait() == 0, player.output
        words = [f"/waiting_words {i}" for i in range(COUNT)]
        listener.wait_for_text(words[-1])
    finally:
        os.kill(listener.process.pid, signal.SIGCONT)
        load.stop()
    assert [line for line in listener.lines if line.startswith("/waiting")] == words
    assert "may miss messages" not in player.output
