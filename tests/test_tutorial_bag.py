"""The "Recording and playing back data" tutorial (ROS 2 Jazzy, Beginner: CLI tools), typed as
printed: `ros2 bag record`, `ros2 bag info`, `ros2 bag play` against this project's turtlesim,
and the page's service part against a service with introspection enabled.

turtlesim runs as a process, headless; `ros2 topic pub -r 10 /turtle1/cmd_vel ...` is the
learner's turtle_teleop_key. Each command runs in a `bag_files` folder, as the page has it.
What is checked: the recorder's and player's log lines (rosbag2's, Jazzy), `ros2 bag info`'s
layout with counts that an independent reader (rosbags) finds in the bag, and the turtle moving
again when the bag plays.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from helpers import BIN, NodeProcess, fails, run, spin_until
from mcap.reader import make_reader
from rclpy.node import Node
from rclpy.qos import qos_profile_services_default
from rclpy.service_introspection import ServiceIntrospectionState
from ros_tutorials_interfaces.srv import AddTwoInts
from rosbags.rosbag2 import Reader
from turtlesim.msg import Pose

HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
# The learner's arrow keys: a slow arc that stays well inside the 11 m square.
TWIST = "{linear: {x: 1.0}, angular: {z: 0.5}}"
LOG = r"\[INFO\] \[\d+\.\d+\] \[{node}\]: {text}"


def ros2_in(folder: Path, *argv: str) -> NodeProcess:
    """`ros2 ARGV...` typed in folder (the page's bag_files), as a real process."""
    code = (
        f"import os, sys; os.chdir({str(folder)!r}); sys.argv = {['ros2', *argv]!r}; "
        "from ros2cmd.cli import main; sys.exit(main())"
    )
    return NodeProcess("-c", code)


def log_lines(output: str, node: str) -> list[str]:
    """The messages of node's INFO lines, in order, each checked for rcutils' format."""
    found = []
    for line in output.splitlines():
        if f"] [{node}]: " in line:
            assert re.fullmatch(LOG.format(node=node, text=".*"), line), line
            found.append(line.split("]: ", 1)[1])
    return found


def in_order(lines: list[str], expected: list[str]) -> None:
    """expected appear among lines in this order (other lines may come between)."""
    position = 0
    for text in expected:
        assert text in lines[position:], f"{text!r} missing after {lines[:position]}: {lines}"
        position = lines.index(text, position) + 1


def counts_with_rosbags(folder: Path) -> dict[str, int]:
    with Reader(folder) as reader:
        counts: dict[str, int] = {}
        for connection, _time, _raw in reader.messages():
            counts[connection.topic] = counts.get(connection.topic, 0) + 1
    return counts


@pytest.fixture
def turtle(ros_domain: int, tmp_path: Path):
    """turtlesim_node and the moving turtle (`ros2 topic pub -r 10`), and the bag_files folder."""
    folder = tmp_path / "bag_files"  # mkdir bag_files; cd bag_files
    folder.mkdir()
    sim = NodeProcess(str(BIN / "ros2"), "run", "turtlesim", "turtlesim_node", env=HEADLESS)
    teleop = NodeProcess(
        str(BIN / "ros2"), "topic", "pub", "-r", "10", "/turtle1/cmd_vel",
        "geometry_msgs/msg/Twist", TWIST,
    )  # fmt: skip
    try:
        sim.wait_for_text("Spawning turtle [turtle1]")
        yield folder, sim, teleop
    finally:
        teleop.kill()
        sim.kill()


def record_while(recorder: NodeProcess, teleop: NodeProcess, commands: int) -> None:
    """Let the recorder record at least `commands` more velocity commands, then Ctrl-C it.

    The teleop publishes two more than that: one that may go out while the new subscription
    is still being matched with the teleop's publisher (a volatile topic keeps nothing for a
    late subscriber, in ROS 2 too), and one still on its way when Ctrl-C comes."""
    recorder.wait_for_text("Recording...")
    recorder.wait_for_text("All requested topics are subscribed. Stopping discovery...")
    sent = teleop.output.count("publishing #")
    teleop.wait_for_output(
        lambda lines: sum("publishing #" in line for line in lines) >= sent + commands + 2,
        timeout=60,
        what=f"{commands} more commands",
    )
    assert recorder.interrupt() == 0, recorder.output


def test_record_a_single_topic(turtle) -> None:
    """3.1: `ros2 bag record /turtle1/cmd_vel`, Ctrl-C, a rosbag2_<date-time> folder."""
    folder, _sim, teleop = turtle
    recorder = ros2_in(folder, "bag", "record", "/turtle1/cmd_vel")
    try:
        record_while(recorder, teleop, 10)
    finally:
        recorder.kill()
    assert "Traceback" not in recorder.output
    lines = log_lines(recorder.output, "rosbag2_recorder")
    in_order(
        lines,
        [
            "Press SPACE for pausing/resuming",
            "Listening for topics...",
            "Subscribed to topic '/turtle1/cmd_vel'",
            "Recording...",
            "All requested topics are subscribed. Stopping discovery...",
            "Pausing recording.",
            "Recording stopped",
        ],
    )
    assert lines.count("Subscribed to topic '/turtle1/cmd_vel'") == 1
    (bag,) = list(folder.iterdir())
    assert re.fullmatch(r"rosbag2_\d{4}_\d\d_\d\d-\d\d_\d\d_\d\d", bag.name), bag.name
    assert sorted(p.name for p in bag.iterdir()) == ["metadata.yaml", f"{bag.name}_0.mcap"]
    counts = counts_with_rosbags(bag)
    assert set(counts) == {"/turtle1/cmd_vel"} and counts["/turtle1/cmd_vel"] >= 10


def test_record_subset_inspect_and_play_it_back(turtle, executor) -> None:
    """3.2, 4 and 5: `ros2 bag record -o subset ...`, `ros2 bag info subset`, `ros2 bag play
    subset` moving the turtle again once the teleop is stopped."""
    folder, _sim, teleop = turtle
    recorder = ros2_in(folder, "bag", "record", "-o", "subset", "/turtle1/cmd_vel", "/turtle1/pose")
    try:
        record_while(recorder, teleop, 30)
    finally:
        recorder.kill()
    lines = log_lines(recorder.output, "rosbag2_recorder")
    for topic in ("/turtle1/cmd_vel", "/turtle1/pose"):
        assert f"Subscribed to topic '{topic}'" in lines
    in_order(lines, ["Listening for topics...", "Recording...", "Recording stopped"])

    # 4: ros2 bag info subset
    info = ros2_in(folder, "bag", "info", "subset")
    assert info.wait() == 0, info.output
    counts = counts_with_rosbags(folder / "subset")
    text = info.output
    layout = [
        r"",
        r"Files:             subset_0\.mcap",
        r"Bag size:          \d+\.\d KiB",
        r"Storage id:        mcap",
        r"ROS Distro:        jazzy",
        r"Duration:          \d+\.\d{9}s",
        r"Start:             [A-Z][a-z]{2} [ \d]\d \d{4} \d\d:\d\d:\d\d\.\d{9} \(\d+\.\d{9}\)",
        r"End:               [A-Z][a-z]{2} [ \d]\d \d{4} \d\d:\d\d:\d\d\.\d{9} \(\d+\.\d{9}\)",
        rf"Messages:          {sum(counts.values())}",
        r"Topic information: Topic: /turtle1/\w+ \| .*",
        r"                   Topic: /turtle1/\w+ \| .*",
        r"Service:           0",
        r"Service information: ",
    ]
    printed = text.split("\n")
    assert len(printed) == len(layout), text
    for pattern, line in zip(layout, printed, strict=True):
        assert re.fullmatch(pattern, line), (pattern, line)
    assert (
        f"Topic: /turtle1/cmd_vel | Type: geometry_msgs/msg/Twist | "
        f"Count: {counts['/turtle1/cmd_vel']} | Serialization Format: cdr"
    ) in text
    assert (
        f"Topic: /turtle1/pose | Type: turtlesim/msg/Pose | "
        f"Count: {counts['/turtle1/pose']} | Serialization Format: cdr"
    ) in text
    assert counts["/turtle1/cmd_vel"] >= 30
    assert counts["/turtle1/pose"] > counts["/turtle1/cmd_vel"]  # every 16 ms against 10 Hz

    # 5: Ctrl-C the teleop; the turtle stops (a command older than 1 s is dropped).
    teleop.interrupt()
    node = Node("bag_tutorial_watcher", context=executor.context)
    executor.add_node(node)
    poses: list[Pose] = []
    node.create_subscription(Pose, "/turtle1/pose", poses.append, 1000)
    # Played poses move (the recorded ones); turtlesim's own, at rest, do not.
    spin_until(executor, lambda: any(p.linear_velocity == 0.0 for p in poses), what="turtle stop")
    before = [p for p in poses if p.linear_velocity == 0.0][-1]
    player = ros2_in(folder, "bag", "play", "subset")
    spin_until(executor, lambda: player.process.poll() is not None, timeout=60, what="play")
    assert player.wait() == 0, player.output
    in_order(
        log_lines(player.output, "rosbag2_player"),
        [
            "Set rate to 1",
            "Adding keyboard callbacks.",
            "Press SPACE for Pause/Resume",
            "Press CURSOR_RIGHT for Play Next Message",
            "Press CURSOR_UP for Increase Rate 10%",
            "Press CURSOR_DOWN for Decrease Rate 10%",
            "Playback until timestamp: -1",
        ],
    )
    seen = len(poses)
    spin_until(
        executor,
        lambda: any(p.linear_velocity == 0.0 for p in poses[seen:]),
        what="the turtle at rest after the bag played",
    )
    after = next(p for p in poses[seen:] if p.linear_velocity == 0.0)
    moved = math.hypot(after.x - before.x, after.y - before.y)
    assert moved > 1.0, (before, after)  # 3 s of 1 m/s commands, less what discovery lost


def test_record_inspect_and_replay_a_service(ros_domain, tmp_path, executor) -> None:
    """The page's service part: `ros2 bag record --service /add_two_ints`, `ros2 bag info`,
    `ros2 bag play --publish-service-requests` with introspection on service and client."""
    folder = tmp_path / "bag_files"
    folder.mkdir()
    node = Node("introspection_service", context=executor.context)
    executor.add_node(node)
    received: list[tuple[int, int]] = []

    def add(request, response):
        received.append((request.a, request.b))
        response.sum = request.a + request.b
        return response

    service = node.create_service(AddTwoInts, "add_two_ints", add)
    client = node.create_client(AddTwoInts, "add_two_ints")
    for endpoint in (service, client):
        endpoint.configure_introspection(
            node.get_clock(), qos_profile_services_default, ServiceIntrospectionState.CONTENTS
        )
    spin_until(executor, client.service_is_ready, what="the service")

    recorder = ros2_in(folder, "bag", "record", "--service", "/add_two_ints")
    calls: list[int] = []

    def call() -> None:
        calls.append(len(calls))
        client.call_async(AddTwoInts.Request(a=len(calls), b=3))

    node.create_timer(0.2, call)
    try:
        spin_until(executor, lambda: "Recording..." in recorder.output, what="Recording...")
        spin_until(
            executor,
            lambda: "Subscribed to topic '/add_two_ints/_service_event'" in recorder.output,
            what="the service event topic subscribed",
        )
        first = len(calls)
        spin_until(executor, lambda: len(calls) >= first + 10, what="10 calls recorded")
        assert recorder.interrupt() == 0, recorder.output
    finally:
        recorder.kill()
    in_order(
        log_lines(recorder.output, "rosbag2_recorder"),
        [
            "Press SPACE for pausing/resuming",
            "Listening for topics...",
            "Subscribed to topic '/add_two_ints/_service_event'",
            "Recording...",
            "Recording stopped",
        ],
    )
    (bag,) = list(folder.iterdir())
    with open(bag / f"{bag.name}_0.mcap", "rb") as stream:
        reader = make_reader(stream)
        channels = reader.get_summary().channels.values()
        assert [c.topic for c in channels] == ["/add_two_ints/_service_event"]
        events = sum(1 for _ in reader.iter_messages())
        schema = next(iter(reader.get_summary().schemas.values()))
    assert schema.name == "ros_tutorials_interfaces/srv/AddTwoInts_Event"
    assert schema.data.decode().startswith(
        "=" * 80 + "\nSRV: ros_tutorials_interfaces/srv/AddTwoInts\nint64 a\n"
    )
    # Each call: request sent and received, response sent and received (less at the edges).
    assert events >= 4 * 8

    result = run("ros2", "bag", "info", str(bag))
    assert result.returncode == 0, result.stderr
    text = result.stdout
    assert "\nMessages:          0\nTopic information: \nService:           1\n" in text
    assert text.endswith(
        "Service information: Service: /add_two_ints | Type: "
        f"ros_tutorials_interfaces/srv/AddTwoInts | Event Count: {events} | "
        "Serialization Format: cdr\n\n"
    ), text
    verbose = run("ros2", "bag", "info", "-v", str(bag)).stdout
    found = re.search(r"Request Count: (\d+) \| Response Count: (\d+)", verbose)
    requests, responses = int(found.group(1)), int(found.group(2))
    assert 0 < responses <= requests < events, verbose

    # 5: the client stops; the bag's requests go to the service again.
    executor.remove_node(node)
    node.destroy_node()
    server = Node("introspection_service_again", context=executor.context)
    executor.add_node(server)
    replayed: list[tuple[int, int]] = []
    server.create_service(
        AddTwoInts,
        "add_two_ints",
        lambda request, response: replayed.append((request.a, request.b)) or response,
    )
    player = ros2_in(folder, "bag", "play", "--publish-service-requests", bag.name)
    spin_until(executor, lambda: player.process.poll() is not None, timeout=60, what="play")
    assert player.wait() == 0, player.output
    assert "Playback until timestamp: -1" in player.output
    assert replayed, player.output
    # Requests the recording saw, each once (its REQUEST_RECEIVED event, not REQUEST_SENT).
    assert set(replayed) <= set(received) and len(replayed) == len(set(replayed))


def test_bad_input_is_one_line(ros_domain, tmp_path) -> None:
    error = fails("ros2", "bag", "record")
    assert error == (
        "[ERROR] [ros2bag]: Need to specify at least one option out of --all, --all-topics, "
        "--all-services, --services, --topics, --topic-types or --regex"
    )
    (tmp_path / "subset").mkdir()
    result = run("ros2", "bag", "record", "-o", str(tmp_path / "subset"), "/chatter")
    assert result.returncode == 1
    assert (
        result.stderr
        == f"[ERROR] [ros2bag]: Output folder '{tmp_path / 'subset'}' already exists.\n"
    )
    assert "not supported here: --compression-mode" in fails(
        "ros2", "bag", "record", "-a", "--compression-mode", "file"
    )
    result = run("ros2", "bag", "info", str(tmp_path / "nothing"))
    assert result.returncode == 2
    assert "Bag path" in result.stderr and "does not exist!" in result.stderr
    assert "Traceback" not in result.stderr
    result = run("ros2", "bag", "play", str(tmp_path / "subset"), "--rate", "0")
    assert result.returncode == 2 and "is not in the valid range (> 0.0)" in result.stderr
    assert "not a bag" in fails("ros2", "bag", "play", str(tmp_path / "subset"))
