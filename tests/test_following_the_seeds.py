"""Following the seeds: rosrun, roscore, roslaunch as console scripts, and the seeds' own
nodes (AandB, Num, UserRecord) as real processes checked by their log lines.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from helpers import BIN, finished, script

from ros2cmd.errors import ToolError
from ros2cmd.run import translate_arguments
from ros_tutorials_common import packages

ROOT = Path(__file__).resolve().parent.parent


def count(lines: list[str], text: str) -> int:
    return sum(text in line for line in lines)


# -- rosrun: the arguments and the package table, no processes ------------------------------


def test_ros1_arguments_become_one_ros_args_block():
    assert translate_arguments(["2", "3", "__name:=adder", "__ns:=/robot1", "a:=b"]) == [
        "2", "3", "--ros-args", "-r", "__node:=adder", "-r", "__ns:=/robot1", "-r", "a:=b",
    ]  # fmt: skip
    assert translate_arguments(["_talker_str:=Goodbye", "_nested/value:=3"]) == [
        "--ros-args", "-p", "talker_str:=Goodbye", "-p", "nested.value:=3",
    ]  # fmt: skip
    # ROS 2 arguments pass unchanged; ROS 1 forms after an open block join it.
    assert translate_arguments(["--ros-args", "-p", "x:=1", "--", "5", "__name:=n"]) == [
        "--ros-args", "-p", "x:=1", "--", "5", "--ros-args", "-r", "__node:=n",
    ]  # fmt: skip
    assert translate_arguments(["--ros-args", "-r", "a:=b"]) == ["--ros-args", "-r", "a:=b"]
    assert translate_arguments(["-5", "3", "--timeout", "2"]) == ["-5", "3", "--timeout", "2"]
    with pytest.raises(ToolError, match="ROS 2 has no master"):
        translate_arguments(["__master:=http://localhost:11311"])
    # ROS 1 took a relative namespace as global; its private ~name is ROS 2's ~/name.
    assert translate_arguments(["__ns:=r1", "~x:=y"]) == [
        "--ros-args", "-r", "__ns:=/r1", "-r", "~/x:=y",
    ]  # fmt: skip


@pytest.mark.parametrize(
    "arg,message",
    [
        ("__name:=pub-1", "__name:=pub-1: 'pub-1' is not a valid node name (letters, digits"),
        ("__name:=", "__name:=: an empty name is not a valid node name"),
        ("__name:=1st", "'1st' is not a valid node name"),
        ("__ns:=r-1", "'/r-1' is not a valid namespace"),
        ("ros_tutorial_msg:=bad-name", "'bad-name' is not a valid topic or service name"),
        ("_bad-param:=1", "'bad-param' is not a valid parameter name"),
        ("~:=x", "'~' is not a valid topic or service name"),  # rcl refuses a bare ~
        ("chatter:=~", "'~' is not a valid topic or service name"),
        ("arostopic://b:=x", "'arostopic://b' is not a valid topic or service name"),
    ],
)
def test_rosrun_refuses_a_bad_ros1_name_in_one_line_before_the_node_starts(arg, message):
    result = finished("rosrun", "ros_tutorials_topic", "topic_publisher", arg)
    assert result.returncode == 1 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and message in result.stderr
    assert "lexeme" not in result.stderr and "Traceback" not in result.stderr


def test_the_seeds_package_names_find_this_projects_executables():
    def module(package: str, executable: str) -> str:
        return packages.module_of(packages.command(package, executable))

    assert module("beginner_tutorials", "talker") == "ros_tutorials_topic.talker"
    assert module("beginner_tutorials", "add_two_ints_server") == (
        "ros_tutorials_service.add_two_ints_server"
    )
    assert module("beginner_tutorials", "aandb_listener") == "ros_tutorials_topic.aandb_listener"
    assert module("rospy_tutorials", "add_two_ints_client") == (
        "ros_tutorials_service.add_two_ints_client"
    )
    # Seed 003's pub_sub publisher ends up sending Num: its name here is num_publisher.
    assert module("pub_sub", "publisher") == "ros_tutorials_topic.num_publisher"
    assert module("pub_sub", "subscriber") == "ros_tutorials_topic.num_subscriber"
    # Seed 003's AddTwoInts package is called `service` (targets add_two_int and client).
    assert module("service", "add_two_ints_server") == "ros_tutorials_service.add_two_ints_server"
    assert module("service", "add_two_int") == "ros_tutorials_service.add_two_ints_server"
    assert module("service", "client") == "ros_tutorials_service.add_two_ints_client"
    # Seed 004's rospy scripts print what the seed shows (workshop_*), not seed 001's lines.
    assert module("my_package", "talker.py") == "ros_tutorials_topic.workshop_talker"
    assert module("my_package", "listener.py") == "ros_tutorials_topic.workshop_listener"
    assert (
        module("my_package", "add_two_ints_client.py")
        == "ros_tutorials_service.workshop_add_two_ints_client"
    )
    assert module("my_package", "dynamics_talker.py") == "ros_tutorials_parameter.talker"
    assert module("ros_tutorials_topic", "topic_publisher") == "ros_tutorials_topic.publisher"
    with pytest.raises(packages.UnknownExecutable, match="has no executable 'nope'; it has: "):
        packages.command("beginner_tutorials", "nope")
    # ROS 1's `rosrun rqt_graph rqt_graph`: a tool of this project, named twice.
    assert packages.module_of(packages.command("ros2", "ros2")) == "ros2cmd.entry"
    with pytest.raises(packages.UnknownExecutable, match="unknown package 'ros2'"):
        packages.command("ros2", "rosrun")


# -- rosrun, roslaunch, roscore as processes ---------------------------------------------------


def test_rosrun_unknown_names_say_the_candidates_in_one_line():
    for args, expected in [
        (("nope", "talker"), "unknown package 'nope'; known packages: "),
        (("ros_tutorials_topic", "nope"), "has no executable 'nope'; it has: "),
        (("beginner_tutorials",), "beginner_tutorials has: aandb_listener, aandb_talker"),
    ]:
        result = finished("rosrun", *args)
        assert result.returncode == 1, result
        lines = result.stderr.strip().splitlines()
        assert len(lines) == 1 and expected in lines[0], result.stderr
    # A seed's name is offered for its typo.
    assert (
        "known packages: beginner_tutorials, "
        in finished("rosrun", "beginner_tutorial", "x").stderr
    )
    result = finished("rosrun", "ros_tutorials_topic", "talker", "__master:=http://x:11311")
    assert result.returncode == 1 and "ROS 2 has no master" in result.stderr
    assert "Traceback" not in result.stderr
    assert finished("rosrun", "-h").returncode == 0
    assert finished("ros2", "run", "nope", "x").returncode == 1


def test_rosrun_of_an_rqt_tool_opens_it_in_the_browser(node_process):
    """Seed 004 runs `rosrun rqt_publisher rqt_publisher` and `rosrun rqt_bag rqt_bag`:
    where there is no display, the link to the view at that tool; a tool named once says
    how it is named."""
    env = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
    for package, fragment in (("rqt_publisher", "#publisher"), ("rqt_bag", "#bag")):
        tool = node_process(str(BIN / "rosrun"), package, package, "--port", "0", env=env)
        line = tool.wait_for_text("in a browser")[-1]
        assert re.search(r"Open http://127\.0\.0\.1:\d+/rqt\?token=[\w-]+" + fragment, line)
    result = finished("rosrun", "rqt_graph")
    assert result.returncode == 1
    assert "rqt_graph has: rqt_graph" in result.stderr.strip().splitlines()[0]


def test_rosrun_runs_the_seeds_talker_and_listener_with_ros1_arguments(node_process):
    listener = node_process(script("rosrun"), "rospy_tutorials", "listener", "chatter:=other")
    talker = node_process(
        script("rosrun"), "beginner_tutorials", "talker",
        "__name:=my_talker", "__ns:=/robot1", "chatter:=/other",
    )  # fmt: skip
    talker.wait_for_text("[robot1.my_talker]: hello world")
    listener.wait_for_text("[listener]: I heard: [hello world", 2)
    assert talker.interrupt() == 0  # the node's own exit status: rosrun became the node
    assert listener.interrupt() == 0


def test_seed_004s_rospy_scripts_print_what_the_seed_shows(node_process):
    # The seed: rospy.loginfo("hello world"); rospy.get_caller_id() + "Receive : %s";
    # print "Ready to add two ints.", "Returning [%s + %s = %s]", "Requesting %s+%s", ...
    listener = node_process(script("rosrun"), "my_package", "listener.py")
    talker = node_process(script("rosrun"), "my_package", "talker.py")
    talker.wait_for_output(lambda lines: any(x.endswith("[talker]: hello world") for x in lines))
    listener.wait_for_text("[listener]: /listenerReceive : hello world")
    assert talker.interrupt() == 0 and listener.interrupt() == 0
    server = node_process(script("rosrun"), "my_package", "add_two_ints_server.py")
    server.wait_for_text("Ready to add two ints.")
    client = finished("rosrun", "my_package", "add_two_ints_client.py", "1", "2")
    assert (client.returncode, client.stdout) == (0, "Requesting 1+2\n1 + 2 = 3\n"), client
    server.wait_for_text("Returning [1 + 2 = 3]")
    assert server.interrupt() == 0
    usage = finished("rosrun", "my_package", "add_two_ints_client.py", "1")
    assert usage.returncode == 1 and usage.stdout.endswith(" [x y]\n"), usage


def test_rosrun_private_parameter_and_ros2cli_run(node_process):
    talker = node_process(
        script("ros2"), "run", "my_package", "dynamics_talker.py", "_talker_str:=Goodbye"
    )
    talker.wait_for_text("[dynamics_talker]: Goodbye", 2)
    assert talker.interrupt() == 0


def test_roslaunch_is_the_launcher_and_finds_the_seeds_launch_files():
    result = finished("roslaunch", "my_package", "talker.launch", "--print")
    assert result.returncode == 0, result.stderr
    assert "ros_tutorials_topic.workshop_talker" in result.stdout and "/talker" in result.stdout
    result = finished("roslaunch", "ros_tutorials_topic", "union.launch", "--print")
    assert result.returncode == 0 and result.stdout.count("ros_tutorials_topic.publisher") == 2
    result = finished("roslaunch", "my_package", "nope.launch")
    assert result.returncode == 1 and "my_package has no launch file 'nope.launch'" in (
        result.stderr
    )


@pytest.mark.parametrize("command", [("roscore",)])
def test_roscore_explains_discovery_and_waits_for_ctrl_c(node_process, command):
    core = node_process(script(command[0]), *command[1:])
    lines = core.wait_for_output(
        lambda lines: any("Ctrl-C" in line for line in lines), what="the explanation"
    )
    text = "\n".join(lines)
    assert "ROS 2 has no master" in text
    assert re.search(r"ROS_DOMAIN_ID=\d+: only nodes with the same domain id", text)
    assert "ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST: only nodes on this machine" in text
    assert core.process.poll() is None, "roscore must wait until Ctrl-C"
    assert core.interrupt() == 0


# -- the seeds' own nodes ------------------------------------------------------------------------


def test_aandb_talker_and_listener_log_the_seed_lines(node_process):
    listener = node_process("-m", "ros_tutorials_topic.aandb_listener")
    talker = node_process(script("rosrun"), "beginner_tutorials", "aandb_talker")
    talker.wait_for_text("[talker]: msg a: 1.000000, msg b:2.000000")
    listener.wait_for_text("[listener]: I heard: msg:a 1.000000, msg:b 2.000000", 2)
    assert talker.interrupt() == 0 and listener.interrupt() == 0


def test_num_publisher_and_subscriber_count_as_the_seed(node_process):
    subscriber = node_process(script("num_subscriber"))
    publisher = node_process(script("rosrun"), "pub_sub", "publisher")
    lines = subscriber.wait_for_text("[sub]: I heard: [", 3)
    heard = [int(m.group(1)) for line in lines if (m := re.search(r"I heard: \[(\d+)\]", line))]
    assert heard == list(range(heard[0], heard[0] + len(heard))) and heard[0] >= 1
    assert publisher.interrupt() == 0 and subscriber.interrupt() == 0


def test_user_record_publisher_and_subscriber(node_process):
    subscriber = node_process(script("user_record_subscriber"))
    publisher = node_process(script("user_record_publisher"))
    publisher.wait_for_text("first_name: Ada, last_name: Lovelace, age: 36, score: ")
    subscriber.wait_for_text("[user_record_subscriber]: Receive : Ada Lovelace, age 36, ", 2)
    assert publisher.interrupt() == 0 and subscriber.interrupt() == 0


def test_rospack_finds_packages_for_roscd():
    result = finished("rospack", "find", "ros_tutorials_topic")
    assert (
        result.returncode == 0 and Path(result.stdout.strip(), "launch", "union.launch").is_file()
    )
    result = finished("rospack", "find", "ros_tutorials_interfaces")
    assert Path(result.stdout.strip(), "msg", "Num.msg").is_file()  # the source, to add to
    assert (
        finished("rospack", "find", "pub_sub").stdout
        == finished("rospack", "find", "ros_tutorials_topic").stdout
    )
    result = finished("rospack", "find", "nope")
    assert result.returncode == 1 and "unknown package 'nope'; known packages: " in result.stderr
    assert "std_msgs " in finished("rospack", "list").stdout


def test_rosmsg_finds_the_seeds_messages_under_their_package_names():
    assert finished("rosmsg", "show", "pub_sub/Num").stdout == "int64 num\n"  # seed 003
    assert finished("rosmsg", "show", "beginner_tutorials/AandB").stdout == "float32 a\nfloat32 b\n"
    result = finished("rossrv", "show", "my_package/AddTwoInts")  # seed 004
    assert result.stdout == "int64 a\nint64 b\n---\nint64 sum\n"
    # Seed 003's service package, and seed 000's lesson packages (their types live in
    # ros_tutorials_interfaces here).
    assert finished("rossrv", "show", "service/AddTwoInts").stdout == result.stdout
    assert "int32 data" in finished("rosmsg", "show", "ros_tutorials_topic/MsgTutorial").stdout
    srv = finished("rossrv", "show", "ros_tutorials_service/SrvTutorial").stdout
    assert srv == "int64 a\nint64 b\n---\nint64 result\n"
    assert "MsgTutorial" in finished("rosmsg", "package", "ros_tutorials_topic").stdout


@pytest.mark.parametrize(
    "args,message",
    [
        (
            ("rosmsg", "show", "ros_tutorials_topic/Nope"),
            "ros_tutorials_topic's types are in ros_tutorials_interfaces, which has no message "
            "'Nope'; `rosmsg list` shows every message type",
        ),
        (
            ("rossrv", "show", "nope_pkg/AddTwoInts"),
            # example_interfaces (the introspection demo's) has one too, as in ROS 2
            "did you mean example_interfaces/srv/AddTwoInts or "
            "ros_tutorials_interfaces/srv/AddTwoInts?",
        ),
        (("rosmsg", "show", "nope_pkg/Nope"), "no interface package 'nope_pkg'; `rosmsg list`"),
        (("rossrv", "show", "Nope"), "unknown service type 'Nope'; `rossrv list`"),
    ],
)
def test_an_unknown_type_name_points_to_the_list_or_the_right_package(args, message):
    result = finished(*args)
    assert result.returncode == 1 and result.stderr.count("\n") == 1
    assert message in result.stderr


def test_rosrun_refuses_malformed_ros_arguments_in_one_line_before_the_node_starts():
    # The node is plain rclpy (rclpy.init's traceback, as any ROS 2 node): rosrun checks first.
    result = finished("rosrun", "beginner_tutorials", "aandb_talker", "--ros-args", "-r", "bad")
    assert result.returncode == 1 and result.stderr.count("\n") == 1, result.stderr
    assert "error: invalid ROS arguments:" in result.stderr
    assert "Couldn't parse remap rule" in result.stderr


@pytest.mark.parametrize(
    "command,expected",
    [
        (("roscd", "ros_tutorials_topic"), f"type: cd {ROOT / 'ros_tutorials_topic'}"),
        (("roscd", "ros_tutorials_topic/launch"), f"cd {ROOT / 'ros_tutorials_topic/launch'}"),
        (("roscd", "ros_tutorials_topic/src"), "ros_tutorials_topic (it has no src/ here)"),
        (("roscd", "nope"), "unknown package 'nope'"),
        (("roscd",), "usage: roscd PKG[/DIR]"),
        (("rosed", "ros_tutorials_topic", "talker.py"), "ros_tutorials_topic/talker.py"),
        # Seed 000's C++ file: the lesson module that runs as service_client here.
        (
            ("rosed", "ros_tutorials_service", "service_client.cpp"),
            "ros_tutorials_service has no service_client.cpp here; its node service_client is "
            f"client.py: type: ${{EDITOR:-nano}} {ROOT / 'ros_tutorials_service/client.py'}",
        ),
        (
            ("rosed", "ros_tutorials_service/src", "service_client.cpp"),
            f"type: ${{EDITOR:-nano}} {ROOT / 'ros_tutorials_service/client.py'}",
        ),
        (("rosed", "ros_tutorials_topic", "nope.py"), "ros_tutorials_topic has no file nope.py"),
        (("catkin_make",), "run `make interfaces`"),
        (("catkin_make",), "type: colcon build, then source install/setup.bash"),
        (
            ("catkin_create_pkg", "beginner_tutorials", "std_msgs", "rospy", "roscpp"),
            "type: ros2 pkg create --build-type ament_python beginner_tutorials "
            "--dependencies std_msgs rclpy",
        ),
        (("catkin_init_workspace",), "mkdir -p ~/ros2_ws/src"),
        (("roscp", "ros_tutorials_topic", "talker.py", "."), "type: cp "),
        # A .srv the package does not hold: the interface package's, where it is.
        (
            ("roscp", "rospy_tutorials", "AddTwoInts.srv", "srv/AddTwoInts.srv"),
            f"type: cp {ROOT / 'interfaces/ros_tutorials_interfaces/srv/AddTwoInts.srv'} "
            "srv/AddTwoInts.srv",
        ),
        (
            ("roscp", "ros_tutorials_service", "AddTwoInts.srv", "srv/"),
            f"type: cp {ROOT / 'interfaces/ros_tutorials_interfaces/srv/AddTwoInts.srv'} srv/",
        ),
        (("roscp", "ros_tutorials_topic", "Nope.srv", "."), "ros_tutorials_topic has no file"),
        (("roscp", "nope", "a", "b"), "unknown package 'nope'"),
        (("roswtf",), "here: ros2 doctor"),
    ],
)
def test_ros1_shell_commands_say_what_to_type_instead(command, expected):
    """roscd, rosed, catkin_make and rviz, typed as the seeds do: one line, exit 1, not
    'command not found'."""
    result = finished(*command)
    assert result.returncode == 1 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and expected in result.stderr, result.stderr
