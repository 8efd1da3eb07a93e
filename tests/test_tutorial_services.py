"""The ROS 2 Jazzy tutorial "Understanding services", typed as printed, against turtlesim and
the service introspection demo (demo_nodes_cpp's introspection_service and introspection_client).

Each command is run as the page has it; its output is compared with the page's output block.
"""

from __future__ import annotations

import re

import pytest
import yaml
from helpers import BIN, at_once, fails, ok
from helpers import run as tool

from ros_tutorials_common import packages

HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
WAITING = "waiting for service to become available..."

# The page's `ros2 service list`, the lines of the node this project runs (turtlesim; the
# page also runs turtle_teleop_key, whose /teleop_turtle/* services are the same six).
PAGE_LIST = """\
/clear
/kill
/reset
/spawn
/turtle1/set_pen
/turtle1/teleport_absolute
/turtle1/teleport_relative
/turtlesim/describe_parameters
/turtlesim/get_parameter_types
/turtlesim/get_parameters
/turtlesim/list_parameters
/turtlesim/set_parameters
/turtlesim/set_parameters_atomically""".splitlines()
PAGE_LIST_T = """\
/clear [std_srvs/srv/Empty]
/kill [turtlesim/srv/Kill]
/reset [std_srvs/srv/Empty]
/spawn [turtlesim/srv/Spawn]
/turtle1/set_pen [turtlesim/srv/SetPen]
/turtle1/teleport_absolute [turtlesim/srv/TeleportAbsolute]
/turtle1/teleport_relative [turtlesim/srv/TeleportRelative]""".splitlines()
PAGE_INFO = "Type: std_srvs/srv/Empty\nClients count: 0\nServices count: 1\n"
PAGE_SPAWN_SRV = """\
float32 x
float32 y
float32 theta
string name # Optional.  A unique name will be created and returned if this is empty
---
string name
"""
PAGE_SPAWN = """\
requester: making request: turtlesim.srv.Spawn_Request(x=2.0, y=2.0, theta=0.2, name='')

response:
turtlesim.srv.Spawn_Response(name='turtle2')

"""
CLEAR = """\
requester: making request: std_srvs.srv.Empty_Request()

response:
std_srvs.srv.Empty_Response()

"""
NO_PUBLISHERS = (
    "No publishers on topic '/add_two_ints/_service_event'; "
    "is service introspection on the client or server enabled?"
)


def called(output: str) -> str:
    """A call's output without the line ros2service prints when the server is not seen at once."""
    return output.removeprefix(WAITING + "\n")


@pytest.fixture
def turtlesim(own_domain, node_process):  # the page: only what the test starts
    sim = node_process(str(BIN / "ros2"), "run", "turtlesim", "turtlesim_node", env=HEADLESS)
    sim.wait_for_text("Spawning turtle [turtle1]")
    return sim


@pytest.mark.long  # the page, command by command
def test_the_services_page_against_turtlesim(turtlesim):
    # The page's commands that only look (the graph settles once in each, at once).
    listed, typed, types, found, info, spawn_srv = at_once(
        ok,
        ("ros2", "service", "list"),
        ("ros2", "service", "list", "-t"),
        ("ros2", "service", "type", "/clear"),
        ("ros2", "service", "find", "std_srvs/srv/Empty"),
        ("ros2", "service", "info", "/clear"),
        ("ros2", "interface", "show", "turtlesim/srv/Spawn"),
    )
    lines = listed.splitlines()
    assert lines == sorted(lines)
    assert [line for line in lines if line in PAGE_LIST] == PAGE_LIST, listed
    assert [line for line in typed.splitlines() if line in PAGE_LIST_T] == PAGE_LIST_T, typed
    assert types == "std_srvs/srv/Empty\n"
    assert found == "/clear\n/reset\n"
    assert info == PAGE_INFO
    assert spawn_srv == PAGE_SPAWN_SRV

    assert called(ok("ros2", "service", "call", "/clear", "std_srvs/srv/Empty")) == CLEAR
    spawned = ok(
        "ros2",
        "service",
        "call",
        "/spawn",
        "turtlesim/srv/Spawn",
        "{x: 2, y: 2, theta: 0.2, name: ''}",
    )
    assert called(spawned) == PAGE_SPAWN
    turtlesim.wait_for_text("Spawning turtle [turtle2] at x=[2.000000], y=[2.000000]")
    assert "/turtle2/set_pen [turtlesim/srv/SetPen]" in ok("ros2", "service", "list", "-t")


def test_list_count_hidden_services_and_info_verbose(turtlesim):
    goal = "/turtle1/rotate_absolute/_action/send_goal"  # turtlesim's action: hidden services
    listed, counted, hidden, hidden_before, verbose, found, hidden_type = at_once(
        ok,
        ("ros2", "service", "list"),
        ("ros2", "service", "list", "-c"),
        ("ros2", "service", "list", "--include-hidden-services"),
        ("ros2", "service", "--include-hidden-services", "list"),
        ("ros2", "service", "info", "-v", "/spawn"),
        ("ros2", "service", "find", "-c", "std_srvs/srv/Empty"),
        ("ros2", "service", "type", goal, "--include-hidden-services"),
    )
    assert int(counted) == len(listed.splitlines())
    assert goal not in listed.splitlines()
    assert hidden_type == "turtlesim/action/RotateAbsolute_SendGoal\n"
    assert fails("ros2", "service", "type", goal) == (
        f"error: '{goal}' is a hidden service; add --include-hidden-services"
    )
    assert goal in hidden.splitlines() and goal in hidden_before.splitlines()
    assert verbose == (
        "Type: turtlesim/srv/Spawn\nClients count: 0\nServices count: 1\n  Node: /turtlesim\n"
    )
    assert found == "2\n"


def _events(text: str) -> list[dict]:
    """The events `ros2 service echo` printed (YAML documents ended by '---')."""
    blocks = text.split("\n---\n")[:-1]  # the last may still be half written
    return [yaml.safe_load(block.split(NO_PUBLISHERS + "\n")[-1]) for block in blocks]


# One event as the page prints it with --flow-style: the lines, each as a pattern.
EVENT_LINES = [
    r"info:",
    r"  event_type: (REQUEST_SENT|REQUEST_RECEIVED|RESPONSE_SENT|RESPONSE_RECEIVED)",
    r"  stamp:",
    r"    sec: \d+",
    r"    nanosec: \d+",
    r"  client_gid: \[\d+(, \d+){15}\]",
    r"  sequence_number: \d+",
    r"request: (\[\]|\[\{a: 2, b: 3\}\])",
    r"response: (\[\]|\[\{sum: 5\}\])",
    r"---",
]


def _all_four(events: list[dict]) -> dict[str, dict] | None:
    """The four events of one call (the first with all four seen), by event type."""
    calls: dict[int, dict[str, dict]] = {}
    for event in events:
        # The client's events and the server's carry the same sequence number; the GIDs
        # differ (the client's and the server's own), so key by number only.
        info = event["info"]
        calls.setdefault(info["sequence_number"], {})[info["event_type"]] = event
    return next((found for found in calls.values() if len(found) == 4), None)


@pytest.mark.long  # the demo, as the page enables introspection at run time
def test_service_echo_shows_the_introspection_demo_as_the_page_does(node_process):
    service = node_process(str(BIN / "ros2"), "run", "demo_nodes_cpp", "introspection_service")
    client = node_process(str(BIN / "ros2"), "run", "demo_nodes_cpp", "introspection_client")
    client.wait_for_text("Result of add_two_ints: 5")
    service.wait_for_output(lambda lines: "a: 2 b: 3" in lines, what="the request logged")
    assert "[introspection_service]: Incoming request" in service.output

    # Introspection is off until the parameters say otherwise: echo says why it sees nothing.
    echo = node_process(str(BIN / "ros2"), "service", "echo", "--flow-style", "/add_two_ints")
    echo.wait_for_text(NO_PUBLISHERS)

    # The page's two `ros2 param set` lines, at once as in two terminals.
    enable = [
        ("ros2", "param", "set", f"/introspection_{node}", f"{node}_configure_introspection")
        for node in ("service", "client")
    ]
    enable = [(*command, "contents") for command in enable]
    assert at_once(ok, *enable) == ["Set parameter successful\n"] * 2

    lines = echo.wait_for_output(
        lambda lines: _all_four(_events("\n".join(lines) + "\n")) is not None,
        what="the four events of one call",
    )
    four = _all_four(_events("\n".join(lines) + "\n"))
    assert four is not None
    for sent in ("REQUEST_SENT", "REQUEST_RECEIVED"):
        assert four[sent]["request"] == [{"a": 2, "b": 3}] and four[sent]["response"] == []
    for sent in ("RESPONSE_SENT", "RESPONSE_RECEIVED"):
        assert four[sent]["request"] == [] and four[sent]["response"] == [{"sum": 5}]
    # The client's two events carry the client's GID, the server's two the server's own.
    gid = {kind: event["info"]["client_gid"] for kind, event in four.items()}
    assert gid["REQUEST_SENT"] == gid["RESPONSE_RECEIVED"] != gid["REQUEST_RECEIVED"]
    assert gid["REQUEST_RECEIVED"] == gid["RESPONSE_SENT"] and len(gid["REQUEST_SENT"]) == 16
    # Line by line as the page prints them (after the first, which may have begun mid-call).
    events = lines[lines.index(NO_PUBLISHERS) + 1 :]
    start = events.index("info:")
    whole = events[start : start + len(EVENT_LINES) * 4]
    for i, line in enumerate(whole):
        assert re.fullmatch(EVENT_LINES[i % len(EVENT_LINES)], line), (line, whole)
    assert echo.interrupt() == 0
    assert "Traceback" not in echo.output

    # The parameter takes only the three states, at run time as at start.
    ok(
        "ros2",
        "param",
        "set",
        "/introspection_client",
        "client_configure_introspection",
        "metadata",
    )
    bad = tool(
        "ros2", "param", "set", "/introspection_service", "service_configure_introspection", "all"
    )
    assert "must be one of 'disabled', 'metadata', or 'contents'" in bad.stdout + bad.stderr
    assert "Traceback" not in bad.stderr


@pytest.mark.long  # the Recording page's start-up, with metadata on the client
def test_introspection_set_at_start_and_metadata_only(node_process):
    """As the "Recording and playing back data" and "Service introspection" pages start the
    demo: the parameters given at start-up, the client sending metadata only."""
    node_process(
        str(BIN / "ros2"), "run", "demo_nodes_cpp", "introspection_service",
        "--ros-args", "-p", "service_configure_introspection:=contents",
    )  # fmt: skip
    client = node_process(
        str(BIN / "ros2"), "run", "demo_nodes_cpp", "introspection_client",
        "--ros-args", "-p", "client_configure_introspection:=metadata",
    )  # fmt: skip
    client.wait_for_text("Result of add_two_ints: 5")
    echo = node_process(str(BIN / "ros2"), "service", "echo", "/add_two_ints", "--no-arr")
    lines = echo.wait_for_output(
        lambda lines: _all_four(_events("\n".join(lines) + "\n")) is not None,
        what="the four events of one call",
    )
    assert NO_PUBLISHERS not in lines
    four = _all_four(_events("\n".join(lines) + "\n"))
    assert four is not None
    seq = "<sequence type: example_interfaces/srv/AddTwoInts_{}[1], length: {}>"
    expected = {  # (request, response): the client's events carry no contents
        "REQUEST_SENT": (0, 0),
        "REQUEST_RECEIVED": (1, 0),
        "RESPONSE_SENT": (0, 1),
        "RESPONSE_RECEIVED": (0, 0),
    }
    for kind, (request, response) in expected.items():
        assert four[kind]["info"]["client_gid"] == "<array type: uint8[16]>"
        assert four[kind]["request"] == seq.format("Request", request)
        assert four[kind]["response"] == seq.format("Response", response)

    # A repeated call (-r) runs until Ctrl-C, which ends it normally.
    repeated = node_process(
        str(BIN / "ros2"), "service", "call", "/add_two_ints",
        "example_interfaces/srv/AddTwoInts", "{a: 1, b: 2}", "-r", "10",
    )  # fmt: skip
    repeated.wait_for_text("example_interfaces.srv.AddTwoInts_Response(sum=3)", count=3)
    assert repeated.interrupt() == 0
    assert "requester: making request: example_interfaces.srv.AddTwoInts_Request(a=1, b=2)" in (
        repeated.output
    )
    assert echo.interrupt() == 0
    assert "Traceback" not in echo.output + repeated.output


def test_the_demo_runs_under_demo_nodes_cpp_and_py():
    for package in ("demo_nodes_cpp", "demo_nodes_py"):
        for executable in ("introspection_service", "introspection_client", "introspection"):
            command = packages.command(package, executable)
            assert command[-1] == f"ros_tutorials_demo_nodes.{executable}"


def test_the_pages_python_launch_file_starts_the_service_and_the_client():
    out = ok("ros2", "launch", "demo_nodes_cpp", "introspect_services_launch.py", "--print")
    labels = [line.split("]")[0][1:] for line in out.splitlines() if line.startswith("[")]
    assert labels == ["introspection_service", "introspection_client"]
    assert out.count("options: output=screen") == 2


@pytest.mark.parametrize(
    "args,message",
    [
        (("type", "/nope"), "unknown service '/nope'"),
        (("info", "/nope"), "unknown service '/nope'"),
        (("echo", "/nope"), "unknown service '/nope'"),
        (("call", "/nope", "std_srvs/srv/Empty"), "unknown service '/nope'"),
        (("call", "/clear", "std_srvs/srv/Nope"), "unknown service type 'std_srvs/srv/Nope'"),
        (("find", "nope_srvs/srv/X"), "no interface package 'nope_srvs'"),
        (("echo", "/clear", "std_srvs/srv/Nope"), "unknown service type 'std_srvs/srv/Nope'"),
        (("call", "/spawn", "turtlesim/srv/Spawn", "{q: 1}"), "'q' is not a field"),
        (("call", "/spawn", "turtlesim/srv/Spawn", "{x: abc}"), "x is a number (float)"),
        (("call", "/spawn", "turtlesim/srv/Spawn", "{x: 2"), "invalid YAML"),
    ],
)
def test_bad_input_is_one_line_and_exit_1(ros_domain, args, message):
    result = tool("ros2", "service", *args, "--timeout", "1")
    assert result.returncode == 1, result
    assert "Traceback" not in result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], result.stderr


@pytest.mark.parametrize(
    "args",
    [
        ("call", "/clear", "std_srvs/srv/Empty", "-r", "0"),
        ("call", "/clear", "std_srvs/srv/Empty", "{}", "--stdin"),
        ("call", "/clear"),
        ("echo", "/clear", "-l", "-1"),
        ("list", "--nope"),
    ],
)
def test_usage_errors_exit_2(args):
    result = tool("ros2", "service", *args)
    assert result.returncode == 2, result
    assert "Traceback" not in result.stderr
    assert re.match(r"ros2( service \w+)?: error: ", result.stderr.splitlines()[-1])
