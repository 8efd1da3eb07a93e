"""How the programs end (ros_tutorials_common/shutdown.py): output that cannot be written is
one line and status 1, a reader gone is a quiet 0, and SIGTERM ends a node of the toolkit that
is busy with its messages without a word from its threads."""

from __future__ import annotations

import signal
import subprocess
import threading

import pytest
import rclpy
from geometry_msgs.msg import TransformStamped
from helpers import BIN, TIMEOUT, NodeProcess
from rclpy.node import Node
from tf2_msgs.msg import TFMessage

from ros_tutorials_common import shutdown

FULL_DEVICE = "error: cannot write to standard output: No space left on device"


@pytest.mark.parametrize(
    "command",
    [
        ["ros2", "topic", "list"],
        ["rostopic", "list"],
        ["ros2", "pkg", "list"],
        ["ros2", "interface", "show", "std_msgs/msg/String"],
        ["rospack", "list"],
    ],
    ids=" ".join,
)
def test_output_to_a_full_device_is_one_line_and_status_1(command, ros_domain):
    with open("/dev/full", "w") as full:
        result = subprocess.run(
            [str(BIN / command[0]), *command[1:]],
            stdout=full, stderr=subprocess.PIPE, text=True, timeout=TIMEOUT,
        )  # fmt: skip
    assert result.stderr == FULL_DEVICE + "\n", result.stderr
    assert result.returncode == 1


def test_a_reader_gone_is_a_quiet_end(ros_domain):
    reader = subprocess.Popen(
        [str(BIN / "ros2"), "pkg", "list"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )  # fmt: skip
    try:
        reader.stdout.readline()
        reader.stdout.close()  # `ros2 pkg list | head -1`
        _, errors = reader.communicate(timeout=TIMEOUT)
    finally:
        reader.kill()
    assert errors == ""
    assert reader.returncode == 0


def test_another_files_error_is_not_taken_for_the_output(tmp_path):
    @shutdown.program_main
    def main() -> int:
        print("written")  # standard output is fine
        raise OSError(28, "No space left on device", str(tmp_path / "bag.mcap"))

    with pytest.raises(OSError, match=r"bag\.mcap"):
        main()


FRAMES = 10_000
PER_MESSAGE = 500


def _flood(node: Node, stop: threading.Event) -> None:
    """/tf: world -> f0 ... f9999, PER_MESSAGE transforms a message, over and over."""
    publisher = node.create_publisher(TFMessage, "/tf", 100)
    while not stop.is_set():
        stamp = node.get_clock().now().to_msg()
        for first in range(0, FRAMES, PER_MESSAGE):
            transforms = []
            for index in range(first, first + PER_MESSAGE):
                transform = TransformStamped()
                transform.header.stamp = stamp
                transform.header.frame_id = "world"
                transform.child_frame_id = f"f{index}"
                transform.transform.translation.x = float(index)
                transform.transform.rotation.w = 1.0
                transforms.append(transform)
            publisher.publish(TFMessage(transforms=transforms))


@pytest.mark.parametrize("run", [1, 2, 3])
def test_sigterm_ends_tf2_echo_while_frames_pour_in_without_a_word(run, context):
    node = rclpy.create_node("tf_flood", context=context)
    stop = threading.Event()
    flood = threading.Thread(target=_flood, args=(node, stop), daemon=True)
    flood.start()
    echo = NodeProcess(str(BIN / "ros2"), "run", "tf2_ros", "tf2_echo", "world", "f500", "100")
    try:
        echo.wait_for_text("- Translation: [500.000", count=3, timeout=2 * TIMEOUT)
        echo.process.send_signal(signal.SIGTERM)
        status = echo.wait()
    finally:
        stop.set()
        flood.join(TIMEOUT)
        echo.kill()
        node.destroy_node()
    assert "Exception in thread" not in echo.output, echo.output[-3000:]
    assert "Traceback" not in echo.output, echo.output[-3000:]
    assert status == 0, echo.output[-3000:]
