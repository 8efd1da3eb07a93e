"""The "Understanding nodes" tutorial typed as printed, and `ros2 interface` as the Topics,
Services and Actions pages show it (ROS 2 Jazzy, Beginner: CLI tools).

turtlesim runs as the learner starts it (`ros2 run turtlesim turtlesim_node`, headless); every
command is the installed `ros2`, and what it prints is checked against the page's text,
quoted below.
"""

from __future__ import annotations

import pytest
from helpers import fails, ok, ready, script
from helpers import run as tool

HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
SPAWNED = "Spawning turtle [turtle1]"

# Understanding-ROS2-Nodes.rst, "3 ros2 node info": the page's output for /my_turtle.
NODE_INFO_PAGE = """\
/my_turtle
  Subscribers:
    /parameter_events: rcl_interfaces/msg/ParameterEvent
    /turtle1/cmd_vel: geometry_msgs/msg/Twist
  Publishers:
    /parameter_events: rcl_interfaces/msg/ParameterEvent
    /rosout: rcl_interfaces/msg/Log
    /turtle1/color_sensor: turtlesim/msg/Color
    /turtle1/pose: turtlesim/msg/Pose
  Service Servers:
    /clear: std_srvs/srv/Empty
    /kill: turtlesim/srv/Kill
    /my_turtle/describe_parameters: rcl_interfaces/srv/DescribeParameters
    /my_turtle/get_parameter_types: rcl_interfaces/srv/GetParameterTypes
    /my_turtle/get_parameters: rcl_interfaces/srv/GetParameters
    /my_turtle/list_parameters: rcl_interfaces/srv/ListParameters
    /my_turtle/set_parameters: rcl_interfaces/srv/SetParameters
    /my_turtle/set_parameters_atomically: rcl_interfaces/srv/SetParametersAtomically
    /reset: std_srvs/srv/Empty
    /spawn: turtlesim/srv/Spawn
    /turtle1/set_pen: turtlesim/srv/SetPen
    /turtle1/teleport_absolute: turtlesim/srv/TeleportAbsolute
    /turtle1/teleport_relative: turtlesim/srv/TeleportRelative
  Service Clients:

  Action Servers:
    /turtle1/rotate_absolute: turtlesim/action/RotateAbsolute
  Action Clients:

"""
# C++ turtlesim's rclcpp node subscribes to /parameter_events (its TimeSource); an rclpy
# node, as this project's turtlesim is, does not.
RCLCPP_ONLY = {("Subscribers", "/parameter_events: rcl_interfaces/msg/ParameterEvent")}
SECTIONS = [
    "Subscribers",
    "Publishers",
    "Service Servers",
    "Service Clients",
    "Action Servers",
    "Action Clients",
]


def info_sections(text: str) -> dict[str, list[str]]:
    """`ros2 node info`'s block as {section: [entries]}, checking its layout on the way:
    the node's name, then each `  Section:` followed by `    /name: type` lines, or by
    one empty line when the section has none."""
    lines = text.split("\n")
    sections: dict[str, list[str]] = {}
    for line in lines[1:-1]:
        if line.startswith("  ") and not line.startswith("    "):
            assert line.endswith(":"), line
            current = sections.setdefault(line.strip().rstrip(":"), [])
        elif line:
            assert line.startswith("    /") and ": " in line, line
            current.append(line.strip())
        else:
            assert not current, f"an empty line after entries: {text}"
    assert lines[-1] == ""
    return sections


@pytest.mark.long  # two turtlesim processes and five ros2 commands: 8 to 15 s
def test_the_nodes_page_typed_as_printed(own_domain, node_process):  # the page: only its nodes
    sim = node_process(script("ros2"), "run", "turtlesim", "turtlesim_node", env=HEADLESS)
    sim.wait_for_text(SPAWNED)
    assert ok("ros2", "node", "list").splitlines() == ["/turtlesim"]

    renamed = node_process(
        script("ros2"), "run", "turtlesim", "turtlesim_node",
        "--ros-args", "--remap", "__node:=my_turtle",
        env=HEADLESS,
    )  # fmt: skip
    renamed.wait_for_text(SPAWNED)
    # The page lists /teleop_turtle too (a keyboard node, started in its own terminal).
    assert ok("ros2", "node", "list").splitlines() == ["/my_turtle", "/turtlesim"]
    assert ok("ros2", "node", "list", "-c").strip() == "2"
    hidden = ok("ros2", "node", "list", "--all").splitlines()
    assert {"/my_turtle", "/turtlesim"} < set(hidden)
    assert any(name.startswith("/_ros2cli_") for name in hidden)  # the command's own node

    info = ok("ros2", "node", "info", "/my_turtle")
    assert info.startswith("/my_turtle\n")
    shown, page = info_sections(info), info_sections(NODE_INFO_PAGE)
    assert list(shown) == SECTIONS == list(page)
    for section, entries in page.items():
        expected = {entry for entry in entries if (section, entry) not in RCLCPP_ONLY}
        assert expected <= set(shown[section]), section
        assert shown[section] == sorted(shown[section])
    assert shown["Service Clients"] == shown["Action Clients"] == []
    # An action's topics and services are hidden names: shown only when asked for.
    assert not any("/_action/" in line for line in info.splitlines())
    everything = ok("ros2", "node", "info", "/my_turtle", "--include-hidden")
    assert (
        "    /turtle1/rotate_absolute/_action/send_goal: "
        "turtlesim/action/RotateAbsolute_SendGoal" in everything.splitlines()
    )
    assert "    /turtle1/rotate_absolute/_action/feedback: " in everything


def test_nodes_that_share_a_name_are_warned_about(own_domain, node_process):
    # Two service lesson servers: both are /service_server.
    for _ in range(2):
        ready(node_process("-m", "ros_tutorials_service.server"))
    listed = tool("ros2", "node", "list")
    assert listed.returncode == 0
    assert listed.stdout.splitlines() == ["/service_server", "/service_server"]
    assert listed.stderr.strip() == (
        "WARNING: Be aware that there are nodes in the graph that share an exact name, "
        "which can have unintended side effects."
    )
    info = tool("ros2", "node", "info", "/service_server")
    assert info.returncode == 0
    assert info.stderr.strip() == (
        'There are 2 nodes in the graph with the exact name "/service_server". '
        "You are seeing information about only one of them."
    )
    assert info.stdout.startswith("/service_server\n  Subscribers:\n")


def test_an_unknown_node_is_one_line():
    line = fails("ros2", "node", "info", "/nope", "--timeout", "1")
    assert line.startswith("error: unknown node '/nope'")


# `ros2 interface`: no graph needed.

# Understanding-ROS2-Topics.rst, "6 ros2 interface show": the page shows the nested fields
# indented; ros2interface indents them by a tab.
TWIST_PAGE = """\
# This expresses velocity in free space broken into its linear and angular parts.

    Vector3  linear
            float64 x
            float64 y
            float64 z
    Vector3  angular
            float64 x
            float64 y
            float64 z
"""
# Understanding-ROS2-Services.rst and -Actions.rst, "ros2 interface show".
SHOWN_ON_THE_PAGES = {
    "std_srvs/srv/Empty": "---\n",
    "turtlesim/srv/Spawn": """\
float32 x
float32 y
float32 theta
string name # Optional.  A unique name will be created and returned if this is empty
---
string name
""",
    "turtlesim/action/RotateAbsolute": """\
# The desired heading in radians
float32 theta
---
# The angular displacement in radians to the starting position
float32 delta
---
# The remaining rotation in radians
float32 remaining
""",
}


def test_interface_show_twist_as_the_topics_page():
    shown = ok("ros2", "interface", "show", "geometry_msgs/msg/Twist")
    assert [line.strip() for line in shown.splitlines()] == [
        line.strip() for line in TWIST_PAGE.splitlines()
    ]
    nested = [line for line in shown.splitlines() if line.startswith("\t")]
    assert nested == ["\tfloat64 x", "\tfloat64 y", "\tfloat64 z"] * 2


@pytest.mark.parametrize("type_name", SHOWN_ON_THE_PAGES)
def test_interface_show_as_the_services_and_actions_pages(type_name):
    assert ok("ros2", "interface", "show", type_name) == SHOWN_ON_THE_PAGES[type_name]


def test_interface_show_comment_options():
    # A nested type's comments only with --all-comments; --no-comments drops every comment
    # and empty line, and the text of a field's trailing comment.
    header = "std_msgs/msg/Header"
    everything = ok("ros2", "interface", "show", "--all-comments", header)
    assert "\t# The seconds component, valid over all int32 values." in everything.splitlines()
    assert "# The seconds component" not in ok("ros2", "interface", "show", header)
    spawn = ok("ros2", "interface", "show", "--no-comments", "turtlesim/srv/Spawn")
    # ros2interface cuts a trailing comment where its text starts, leaving the '#'.
    assert spawn.splitlines()[3] == "string name #"
    twist = ok("ros2", "interface", "show", "--no-comments", "geometry_msgs/msg/Twist")
    assert twist.splitlines()[0] == "Vector3  linear"
    assert ok("ros2", "interface", "show", "std_msgs/msg/Empty") == ""


def test_interface_proto_list_package_packages():
    assert ok("ros2", "interface", "proto", "geometry_msgs/msg/Twist") == (
        '"linear:\n  x: 0.0\n  y: 0.0\n  z: 0.0\nangular:\n  x: 0.0\n  y: 0.0\n  z: 0.0\n"\n'
    )
    assert ok("ros2", "interface", "proto", "turtlesim/srv/Spawn", "--no-quotes") == (
        "x: 0.0\ny: 0.0\ntheta: 0.0\nname: ''\n\n"
    )
    listed = ok("ros2", "interface", "list").splitlines()
    titles = [line for line in listed if not line.startswith("    ")]
    assert titles == ["Messages:", "Services:", "Actions:"]
    assert "    geometry_msgs/msg/Twist" in listed
    assert "    turtlesim/action/RotateAbsolute" in listed
    messages = ok("ros2", "interface", "list", "-m").splitlines()
    assert messages[0] == "Messages:" and messages[1:] == sorted(messages[1:])
    assert ok("ros2", "interface", "package", "turtlesim").splitlines() == [
        "turtlesim/action/RotateAbsolute",
        "turtlesim/msg/Color",
        "turtlesim/msg/Pose",
        "turtlesim/srv/Kill",
        "turtlesim/srv/SetPen",
        "turtlesim/srv/Spawn",
        "turtlesim/srv/TeleportAbsolute",
        "turtlesim/srv/TeleportRelative",
    ]
    assert ok("ros2", "interface", "package", "-a", "turtlesim") == (
        "turtlesim/action/RotateAbsolute\n"
    )
    packages = ok("ros2", "interface", "packages").splitlines()
    assert {"geometry_msgs", "turtlesim", "ros_tutorials_interfaces"} <= set(packages)
    assert "turtlesim" in ok("ros2", "interface", "packages", "-a").splitlines()
    assert "std_msgs" not in ok("ros2", "interface", "packages", "-a").splitlines()


@pytest.mark.parametrize(
    "args,message",
    [
        (("show", "nope_msgs/msg/X"), "no interface package 'nope_msgs'"),
        (("show", "geometry_msgs/msg/Nope"), "unknown message type"),
        (("proto", "geometry_msgs/msg/Nope"), "unknown message type"),
        (("package", "nope_msgs"), "unknown interface package 'nope_msgs'"),
    ],
)
def test_interface_errors_are_one_line(args, message):
    assert message in fails("ros2", "interface", *args)


def test_interface_usage_errors_exit_2():
    result = tool("ros2", "interface", "show", "--all-comments", "--no-comments", "x/msg/Y")
    assert result.returncode == 2 and "not allowed with" in result.stderr
