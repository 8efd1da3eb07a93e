"""The ROS 2 Jazzy tutorial "Understanding topics", typed as the page prints it.

This project's turtlesim runs as a process (headless), and every command is the page's own
line through the installed `ros2`, checked against the output the page shows (and, where the
page shows none, against what ros2topic prints): the topic list, the echoed YAML, the
`Type:`/`Publisher count:` lines, `publisher: beginning loop`, `average rate:`, the bandwidth
lines. Then what the page mentions besides: `header: "auto"`, `time_ref: "now"`, SetPen's
`off:` key that YAML 1.1 reads as a boolean, echo's --no-arr, --flow-style and --field, and
bad input, one line each.
"""

from __future__ import annotations

import re
import time

import pytest
from helpers import BIN, fails, ok, run

from ros2cmd.messages import fill_message, message_to_yaml

HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
TWIST = "geometry_msgs/msg/Twist"
# The page's values for the turtle, and the message as `ros2 topic pub` prints it.
TWIST_VALUES = "{linear: {x: 2.0, y: 0.0, z: 0.0}, angular: {x: 0.0, y: 0.0, z: 1.8}}"
TWIST_REPR = (
    "geometry_msgs.msg.Twist(linear=geometry_msgs.msg.Vector3(x=2.0, y=0.0, z=0.0), "
    "angular=geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=1.8))"
)
PAGE_TOPICS = [
    "/parameter_events",
    "/rosout",
    "/turtle1/cmd_vel",
    "/turtle1/color_sensor",
    "/turtle1/pose",
]
PAGE_TOPICS_WITH_TYPES = [
    "/parameter_events [rcl_interfaces/msg/ParameterEvent]",
    "/rosout [rcl_interfaces/msg/Log]",
    "/turtle1/cmd_vel [geometry_msgs/msg/Twist]",
    "/turtle1/color_sensor [turtlesim/msg/Color]",
    "/turtle1/pose [turtlesim/msg/Pose]",
]
TWIST_YAML = ["linear:", "  x: 2.0", "  y: 0.0", "  z: 0.0", "angular:", "  x: 0.0", "  y: 0.0"]
TWIST_YAML += ["  z: 1.8", "---"]
RATE = re.compile(r"average rate: (\d+\.\d{3})")
RATE_DETAILS = re.compile(r"\tmin: \d+\.\d{3}s max: \d+\.\d{3}s std dev: \d+\.\d{5}s window: \d+")


def ros2(node_process, *args: str):
    """A `ros2 ...` command that runs until Ctrl-C, as a process (its own terminal)."""
    return node_process(str(BIN / "ros2"), *args)


def blocks(lines: list[str]) -> list[list[str]]:
    """Echoed messages: the lines of each, '---' included."""
    found, current = [], []
    for line in lines:
        current.append(line)
        if line == "---":
            found.append(current)
            current = []
    return found


@pytest.fixture(scope="class")
def turtlesim(class_own_domain, class_node_process):  # the page: only what the class starts
    """`ros2 run turtlesim turtlesim_node`, headless."""
    sim = class_node_process(str(BIN / "ros2"), "run", "turtlesim", "turtlesim_node", env=HEADLESS)
    sim.wait_for_text("Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]")
    return sim


class TestTheTopicsPage:
    """The page's commands against one turtlesim, in the page's order."""

    def test_topic_list_and_list_t(self, turtlesim):
        listed = ok("ros2", "topic", "list").splitlines()
        typed = ok("ros2", "topic", "list", "-t").splitlines()
        # turtlesim alone in its domain: the page's lines, exactly.
        assert listed == PAGE_TOPICS
        assert typed == PAGE_TOPICS_WITH_TYPES
        assert int(ok("ros2", "topic", "list", "-c")) == len(PAGE_TOPICS)

    def test_echo_info_and_pub(self, turtlesim, node_process):
        echo = ros2(node_process, "topic", "echo", "/turtle1/cmd_vel")
        # The page's publisher is turtle_teleop_key; a steady `ros2 topic pub` stands in.
        pub = ros2(node_process, "topic", "pub", "/turtle1/cmd_vel", TWIST, TWIST_VALUES)
        lines = echo.wait_for_output(lambda lines: "---" in lines, what="an echoed Twist")
        assert blocks(lines)[0] == TWIST_YAML
        # (The echo may print before the publisher's blank line after #1 has been read here.)
        # (Its lines as read: `output` joins them, and a last blank line would be lost.)
        first = pub.wait_for_output(lambda lines: len(lines) >= 3, what="its first lines")
        assert first[:3] == [
            "publisher: beginning loop",
            f"publishing #1: {TWIST_REPR}",
            "",
        ]
        info = ok("ros2", "topic", "info", "/turtle1/cmd_vel")
        assert info.splitlines() == [
            "Type: geometry_msgs/msg/Twist",
            "Publisher count: 1",
            "Subscription count: 2",  # turtlesim and the echo
        ]
        assert pub.interrupt() == 0
        seen = len(blocks(echo.output.splitlines()))  # the echo prints the next one at once
        once = ok(
            "ros2", "topic", "pub", "--once", "-w", "2", "/turtle1/cmd_vel", TWIST, TWIST_VALUES
        )
        # The page's first line, as ros2topic prints it, only while fewer than 2 have matched
        # (its new publisher is usually discovered within a moment, not always).
        waiting = "Waiting for at least 2 matching subscription(s)..."
        assert once.splitlines()[1 if once.startswith(waiting) else 0 :] == [
            "publisher: beginning loop",
            f"publishing #1: {TWIST_REPR}",
            "",
        ]
        echo.wait_for_output(lambda lines: len(blocks(lines)) > seen, what="the --once message")
        assert echo.interrupt() == 0
        assert "Traceback" not in echo.output

    def test_pub_rate_1_and_its_hz(self, turtlesim, node_process):
        pub = ros2(
            node_process, "topic", "pub", "--rate", "1", "/turtle1/cmd_vel", TWIST, TWIST_VALUES
        )
        hz = ros2(node_process, "topic", "hz", "/turtle1/cmd_vel")
        lines = hz.wait_for_output(lambda lines: any(RATE.match(x) for x in lines), what="a rate")
        rate = float(RATE.match(next(x for x in lines if RATE.match(x))).group(1))
        assert 0.5 < rate < 2.0  # "an average reflecting that rate"
        for proc in (hz, pub):
            assert proc.interrupt() == 0

    def test_echo_hz_and_bw_of_the_pose(self, turtlesim, node_process):
        echo = ros2(node_process, "topic", "echo", "/turtle1/pose")
        hz = ros2(node_process, "topic", "hz", "/turtle1/pose")
        bw = ros2(node_process, "topic", "bw", "/turtle1/pose")
        lines = echo.wait_for_output(lambda lines: "---" in lines, what="an echoed pose")
        keys = [line.split(":")[0] for line in blocks(lines)[0]]
        assert keys == ["x", "y", "theta", "linear_velocity", "angular_velocity", "---"]
        lines = hz.wait_for_output(lambda lines: len(lines) >= 2, what="a rate")
        assert RATE.fullmatch(lines[0]) and RATE_DETAILS.fullmatch(lines[1]), lines
        assert 10.0 < float(RATE.match(lines[0]).group(1)) < 100.0  # 62.5 on an idle machine
        lines = bw.wait_for_output(lambda lines: len(lines) >= 3, what="a bandwidth")
        assert lines[0] == "Subscribed to [/turtle1/pose]"
        assert re.fullmatch(r"\d+(\.\d\d KB| B)/s from \d+ messages", lines[1]), lines
        # A Pose is 24 bytes serialized (4 of encapsulation, 5 float32).
        assert lines[2] in (
            "\tMessage size mean: 0.02 KB min: 0.02 KB max: 0.02 KB",
            "\tMessage size mean: 24 B min: 24 B max: 24 B",
        )
        for proc in (echo, hz, bw):
            assert proc.interrupt() == 0
            assert "Traceback" not in proc.output

    def test_echo_flow_style_field_and_once(self, turtlesim):
        flow = ok("ros2", "topic", "echo", "--once", "--flow-style", "/turtle1/pose")
        # rosidl_runtime_py's --flow-style: its mappings stay in block style (only sequences
        # flow), so a Pose prints as without the option.
        assert re.fullmatch(
            r"x: [-\d.e]+\ny: [-\d.e]+\ntheta: [-\d.e]+\nlinear_velocity: [-\d.e]+\n"
            r"angular_velocity: [-\d.e]+\n---\n",
            flow,
        ), flow
        field = ok("ros2", "topic", "echo", "--once", "/turtle1/pose", "--field", "theta")
        value, end = field.splitlines()
        assert end == "---" and float(value) == pytest.approx(float(value))

    def test_a_wrong_type_is_said_not_waited_for_in_silence(self, turtlesim):
        # ros2cli waits (pub --once) or prints nothing (echo) for ever, without a word.
        color = "turtlesim/msg/Color"
        echo = run("ros2", "topic", "echo", "/turtle1/pose", color, "--timeout", "8")
        assert echo.returncode == 0 and echo.stdout == ""
        assert echo.stderr == (
            "warning: /turtle1/pose carries turtlesim/msg/Pose, not turtlesim/msg/Color: "
            "nothing there will match (`ros2 topic type /turtle1/pose` says its type)\n"
        )
        pub = run(
            *("ros2", "topic", "pub", "--once", "--max-wait-time-secs", "3", "/turtle1/cmd_vel"),
            *("turtlesim/msg/Pose", "{x: 2}"),
        )
        assert pub.returncode == 1
        assert pub.stderr.splitlines()[0] == (
            "warning: /turtle1/cmd_vel carries geometry_msgs/msg/Twist, not turtlesim/msg/Pose: "
            "nothing there will match (`ros2 topic type /turtle1/cmd_vel` says its type)"
        )

    def test_topic_find(self, turtlesim):
        assert "/turtle1/cmd_vel" in ok("ros2", "topic", "find", TWIST).splitlines()
        assert "/turtle1/pose" not in ok("ros2", "topic", "find", TWIST).splitlines()

    def test_set_pen_off_key(self, turtlesim):
        # YAML 1.1 reads `off` as false: the field of that name is meant.
        out = ok(
            "ros2", "service", "call", "/turtle1/set_pen", "turtlesim/srv/SetPen",
            "{r: 255, g: 255, b: 255, width: 10, off: 0}",
        )  # fmt: skip
        assert (
            "requester: making request: "
            "turtlesim.srv.SetPen_Request(r=255, g=255, b=255, width=10, off=0)"
        ) in out.splitlines()

    def test_delay_needs_a_header(self, turtlesim):
        assert "msg does not have header" in fails("ros2", "topic", "delay", "/turtle1/pose")


def test_header_auto_and_time_now_are_stamped_at_each_publication(node_process):
    pose = ros2(
        node_process, "topic", "pub", "-r", "10", "/pose", "geometry_msgs/msg/PoseStamped",
        '{header: "auto", pose: {position: {x: 1.0, y: 2.0, z: 3.0}}}',
    )  # fmt: skip
    reference = ros2(
        node_process, "topic", "pub", "-r", "10", "/reference", "sensor_msgs/msg/TimeReference",
        '{header: "auto", time_ref: "now", source: "dumy"}',
    )  # fmt: skip
    first = ok("ros2", "topic", "echo", "--once", "/pose", "--field", "header.stamp.sec")
    assert abs(int(first.splitlines()[0]) - time.time()) < 60
    echoed = ok("ros2", "topic", "echo", "/pose", "--timeout", "3").split("---\n")
    stamps = [
        (m.split("sec: ")[1].split()[0], m.split("nanosec: ")[1].split()[0]) for m in echoed if m
    ]
    assert len(set(stamps)) == len(stamps) > 1, "each message gets a new stamp"
    ref = ok("ros2", "topic", "echo", "--once", "/reference").splitlines()
    assert ref[ref.index("time_ref:") + 1].startswith("  sec: 1")  # not 0: now
    assert "source: dumy" in ref
    delay = ros2(node_process, "topic", "delay", "/pose")
    lines = delay.wait_for_output(lambda lines: len(lines) >= 2, what="a delay")
    assert re.fullmatch(r"average delay: -?\d+\.\d{3}", lines[0]), lines
    assert RATE_DETAILS.fullmatch(lines[1].replace("-", "")), lines
    for proc in (pose, reference, delay):
        assert proc.interrupt() == 0


def test_echo_no_arr_and_flow_style_of_arrays(node_process):
    ros2(
        node_process,
        "topic",
        "pub",
        "-r",
        "10",
        "/arr",
        "std_msgs/msg/Int32MultiArray",
        "{data: [1, 2, 3]}",
    )
    block = ok("ros2", "topic", "echo", "--once", "/arr")
    assert block.splitlines() == [
        "layout:",
        "  dim: []",
        "  data_offset: 0",
        "data:",
        "- 1",
        "- 2",
        "- 3",
        "---",
    ]
    no_arr = ok("ros2", "topic", "echo", "--once", "--no-arr", "/arr")
    assert no_arr.splitlines() == [
        "layout:",
        "  dim: '<sequence type: std_msgs/msg/MultiArrayDimension, length: 0>'",
        "  data_offset: 0",
        "data: '<sequence type: int32, length: 3>'",
        "---",
    ]
    flow = ok("ros2", "topic", "echo", "--once", "--flow-style", "/arr")
    assert flow.splitlines() == [
        "layout:",
        "  dim: []",
        "  data_offset: 0",
        "data: [1, 2, 3]",
        "---",
    ]
    csv = ok("ros2", "topic", "echo", "--once", "--csv", "/arr")
    assert csv == "0,1,2,3\n"


def test_message_yaml_as_rosidl_runtime_py_writes_it():
    from std_msgs.msg import String

    long_text = String(data="word " * 40)
    assert message_to_yaml(long_text) == f"data: '{'word ' * 40}'"  # one line, not folded
    assert message_to_yaml(long_text, truncate_length=10) == "data: word word ..."
    assert message_to_yaml(long_text, no_str=True) == "data: '<string length: <200>>'"
    from turtlesim.srv import SetPen

    pen = fill_message(SetPen.Request(), {"r": 1, False: 1})  # {r: 1, off: 1}
    assert pen.off == 1


@pytest.mark.parametrize(
    "args,message",
    [
        (
            ("pub", "/t", "std_msgs/msg/String", "{nope: 1}"),
            "'nope' is not a field of std_msgs/msg/String (fields: data)",
        ),
        (("pub", "/t", "std_msgs/msg/Strin", "{}"), "unknown message type 'std_msgs/msg/Strin'"),
        (
            ("pub", "/t", "std_msgs/msg/String", "hello"),
            "The passed value needs to be a dictionary in YAML format",
        ),
        (("pub", "/t", TWIST, "{linear: {x: fast}}"), "linear.x is a number (double), got 'fast'"),
        (("pub", "/t", TWIST, "{linear: {x: 1.0}"), "invalid YAML"),
        (
            ("pub", "/t", TWIST, "{linear: {w: 1.0}}"),
            "'w' is not a field of linear (geometry_msgs/msg/Vector3) (fields: x, y, z)",
        ),
        (
            ("echo", "/t", TWIST, "--field", "linear.w"),
            "Invalid field 'linear.w': geometry_msgs/msg/Vector3 has no field 'w' "
            "(fields: x, y, z)",
        ),
        (("echo", "/nope", "--timeout", "1"), "unknown topic '/nope'"),
        (
            ("pub", "/t", TWIST, "{}", "--max-wait-time-secs", "1"),
            "--max-wait-time-secs option is only effective",
        ),
    ],
)
def test_bad_input_is_one_line(args, message):
    line = fails("ros2", "topic", *args)
    assert line.startswith("error: ") and message in line


def test_usage_errors_and_help():
    conflict = ok_or_usage("ros2", "topic", "pub", "--once", "-t", "2", "/t", TWIST)
    assert "not allowed with argument" in conflict
    shown = ok("ros2", "topic", "-h")
    assert "Commands:" in shown
    names = [line.split()[0] for line in shown.split("Commands:\n")[1].splitlines()[:9]]
    assert names == ["bw", "delay", "echo", "find", "hz", "info", "list", "pub", "type"]
    assert "  echo   Output messages from a topic" in shown.splitlines()


def ok_or_usage(*args: str) -> str:
    """A command argparse refuses: exit 2, and its usage error."""
    from helpers import run

    result = run(*args)
    assert result.returncode == 2 and "usage:" in result.stderr, result.stderr
    return result.stderr
