"""TAB completion (ros_tutorials_common/completion.py, ros2cmd/completion.py), through
argcomplete's own protocol, as bash's completion function runs a command: `_ARGCOMPLETE=1`, the
line in COMP_LINE and the cursor in COMP_POINT; the answer, separated by _ARGCOMPLETE_IFS, in
the file _ARGCOMPLETE_STDOUT_FILENAME names. And that activating the environment registers it.

How long a completion takes is measured in benchmarks/completion.py; here the budget is set
generously (ROS_TUTORIALS_COMPLETION_BUDGET), as the machine may be loaded.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest
from helpers import BIN, TIMEOUT, run
from rclpy.node import Node

from ros2cmd.daemon import client as daemon
from ros_tutorials_common.completion import COMMANDS, COMPLETION_BUDGET_VARIABLE


def complete(line: str, env: dict[str, str] | None = None) -> tuple[list[str], str]:
    """What TAB offers at the end of LINE (its first word: the command), and the command's
    standard error (where Python's own -X importtime lines go)."""
    environment = dict(os.environ if env is None else env)
    environment.pop(daemon.NO_DAEMON_VARIABLE, None)  # a learner's shell: the daemon is asked
    environment.update(
        _ARGCOMPLETE="1",
        _ARGCOMPLETE_IFS="\n",
        _ARGCOMPLETE_SHELL="bash",
        COMP_LINE=line,
        COMP_POINT=str(len(line)),
        COMP_TYPE="9",  # TAB
    )
    environment.setdefault(COMPLETION_BUDGET_VARIABLE, str(TIMEOUT))
    with tempfile.NamedTemporaryFile("r") as answer:
        environment["_ARGCOMPLETE_STDOUT_FILENAME"] = answer.name
        try:
            result = subprocess.run(
                [str(BIN / line.split()[0])],
                env=environment,
                stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.PIPE,
                text=True,
                timeout=TIMEOUT,
            )
        except subprocess.TimeoutExpired:
            pytest.fail(f"completing {line!r} did not end within {TIMEOUT:.0f} s")
        assert result.returncode == 0, f"completing {line!r}: status {result.returncode}"
        text = answer.read()
    return [word.strip() for word in text.split("\n") if word.strip()], result.stderr


def offered(line: str) -> list[str]:
    return complete(line)[0]


def test_a_verb():
    assert offered("ros2 to") == ["topic"]
    assert set(offered("ros2 ")) >= {"action", "launch", "node", "run", "topic", "interface"}
    assert "-h" not in offered("ros2 -"), "ros2cli offers no -h/--help"


def test_an_option():
    found = offered("ros2 topic echo --q")
    assert "--qos-profile" in found and "--qos-reliability" in found
    assert all(word.startswith("--q") for word in found)


def test_a_sub_verb_of_a_ros1_tool():
    assert offered("rostopic ec") == ["echo"]
    assert offered("rosservice ca") == ["call"]


def test_a_type_from_the_ament_index():
    found = offered("ros2 interface show geometry_msgs/msg/Tw")
    assert {"geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped"} <= set(found)
    assert offered("rosmsg show geometry_msgs/Twist")[:1] == ["geometry_msgs/Twist"]
    assert "turtlesim/srv/Spawn" in offered("ros2 service call /spawn turtlesim/srv/")


def test_packages_and_their_executables():
    assert "turtlesim" in offered("ros2 run turt")
    executables = offered("ros2 run turtlesim ")
    assert {"turtlesim_node", "turtle_teleop_key", "draw_square", "mimic"} <= set(executables)
    assert "turtlesim_node" in offered("rosrun turtlesim turtlesim_")


def test_launch_files_of_a_package():
    found = offered("ros2 launch ros_tutorials_topic ")
    assert "union.launch" in found, found
    assert "union.launch" in offered("roslaunch ros_tutorials_topic uni")
    assert "ros_tutorials_topic" in offered("ros2 launch ros_tutorials_to")
    # a name that stands for this project's package, as `ros2 launch turtlesim FILE` finds it
    assert "multisim.launch.py" in offered("ros2 launch turtlesim multi")


@pytest.fixture
def running_daemon(ros_domain):
    """The session's daemon (as a learner's `ros2 daemon start`), stopped after the test."""
    env = dict(os.environ)
    env.pop(daemon.NO_DAEMON_VARIABLE)
    started = run("ros2", "daemon", "start", env=env)
    assert started.returncode == 0, started.stderr
    try:
        yield
    finally:
        daemon.stop_quietly()


def _words(found: list[str]) -> list[str]:
    return [word for word in found if not word.startswith("-")]


def _offered_once(line: str, wanted: str) -> list[str]:
    """What LINE offers once it offers WANTED (the daemon discovers a new node's names a
    moment after it starts)."""
    deadline = time.monotonic() + TIMEOUT
    while wanted not in (found := offered(line)):
        if time.monotonic() > deadline:
            pytest.fail(f"{line!r} did not offer {wanted} within {TIMEOUT:.0f} s: {found}")
        time.sleep(0.2)  # paces the asking; each answer is the daemon's at that moment
    return found


def test_live_names_come_from_the_daemon(running_daemon, context):
    from geometry_msgs.msg import Twist

    node = Node("completion_test_node", context=context)
    try:
        topic = f"/turtle_completion_{os.getpid()}/cmd_vel"
        node.create_publisher(Twist, topic, 10)
        found = _offered_once("ros2 topic echo /turtle_completion", topic)
        assert all(name.startswith("/turtle_completion") for name in found)
        # the topic's type (and, as ros2cli's, the options)
        assert _words(offered(f"ros2 topic pub {topic} ")) == ["geometry_msgs/msg/Twist"]
        assert _words(offered(f"rostopic pub {topic} ")) == ["geometry_msgs/Twist"]
        assert topic in offered("rostopic echo /turtle_completion")
        assert "/completion_test_node" in offered("ros2 node info /completion_test")
        assert "/completion_test_node" in offered("ros2 param get /completion_test")
    finally:
        node.destroy_node()


def test_parameter_names_come_from_the_node_through_the_daemon(running_daemon, parameter_lesson):
    _offered_once("ros2 node info /service_serv", "/service_server")
    # the daemon asks the node (its first question to a node may come too late: asked again)
    assert "calculation_method" in _offered_once(
        "ros2 param get /service_server calc", "calculation_method"
    )
    assert "calculation_method" in offered("ros2 param set /service_server ")
    # a question the daemon cannot take is answered as such, at once, and it goes on
    for bad in ({"node": 5, "timeout": 0.1}, {"node": "/service_server", "timeout": "NaN"}):
        answer = daemon._request({"ask": "parameters", **bad}, timeout=TIMEOUT)
        assert answer == {"error": "parameters: a node name and a timeout"}
    nan = {"ask": "parameters", "node": "/service_server", "timeout": float("nan")}
    assert "parameters" in daemon._request(nan, timeout=TIMEOUT)  # no wait, not forever
    assert daemon.ask_parameters("/nobody_here", TIMEOUT) == []
    assert daemon.ask_names(TIMEOUT) is not None


def _daemons_of_domain(domain_id: str) -> list[int]:
    """The processes of `python -m ros2cmd.daemon` started for this domain."""
    found = []
    for entry in Path("/proc").iterdir():
        try:
            command = (entry / "cmdline").read_bytes().split(b"\0")
            environ = (entry / "environ").read_bytes().split(b"\0")
        except (OSError, ValueError):
            continue
        if b"ros2cmd.daemon" in command and f"ROS_DOMAIN_ID={domain_id}".encode() in environ:
            found.append(int(entry.name))
    return found


def test_without_a_daemon_nothing_completes_and_nothing_starts(own_domain):
    """No daemon: a live name completes nothing, and the completion starts no daemon and no
    DDS participant (it does not even load rclpy: Python's -X importtime lists each import)."""
    env = dict(os.environ, PYTHONPROFILEIMPORTTIME="1")
    for line in ("ros2 topic echo /", "rostopic echo /", "ros2 node info /"):
        found, imports = complete(line, env)
        assert found == [], line
        loaded = [row.rsplit("|", 1)[-1].strip() for row in imports.splitlines() if "|" in row]
        assert "argcomplete" in loaded, "the completion did not run"
        assert not [name for name in loaded if name.startswith(("rclpy", "rpyutils"))], line
    assert _daemons_of_domain(str(own_domain)) == []


def test_every_registered_command_answers_the_protocol():
    """The shell runs each registered command to complete it: each must answer (and not run:
    `roslaunch` or `roscore` would otherwise start in the background; complete() fails on a
    command that does not end)."""
    for command in COMMANDS:
        assert offered(f"{command} --he") == [], command  # -h/--help are not offered
        found = offered(f"{command} ")
        assert found or command in ("roscore", "roslaunch-logs"), f"{command}: nothing offered"
    assert "turtlesim" in offered("roscd turt")


BASH = shutil.which("bash")
needs_bash = pytest.mark.skipif(BASH is None, reason="bash is not installed")


def _bash(script: str, interactive: bool, env: dict[str, str] | None = None) -> str:
    flags = ["--norc", "--noprofile", *(["-i"] if interactive else [])]
    result = subprocess.run(
        [BASH, *flags, "-c", script],
        env=env,
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )
    return result.stdout


def _new_terminal() -> dict[str, str]:
    """A new terminal's environment: nothing of this environment activated."""
    env = {name: value for name, value in os.environ.items() if not name.startswith("ROS")}
    env.pop("VIRTUAL_ENV", None)
    env.pop("AMENT_PREFIX_PATH", None)
    env["PATH"] = os.pathsep.join(
        part for part in env.get("PATH", "").split(os.pathsep) if Path(part) != BIN
    )
    return env


@needs_bash
def test_activating_the_environment_registers_completion():
    activate = Path(sys.prefix) / "bin" / "activate"
    shown = _bash(f"source {activate}\ncomplete -p {' '.join(COMMANDS)}", True, _new_terminal())
    for command in COMMANDS:
        assert f"-F _python_argcomplete {command}\n" in shown, shown
    # bash's completion function, as TAB calls it: the whole way, shell to command and back
    press_tab = (
        f"source {activate}\nexport {COMPLETION_BUDGET_VARIABLE}={TIMEOUT}\n"
        'COMP_LINE="rostopic ec"; COMP_POINT=11; COMP_TYPE=9\n'
        '_python_argcomplete rostopic; echo "[${COMPREPLY[*]}]"'
    )
    assert _bash(press_tab, True, _new_terminal()).strip() == "[echo ]"  # the word, a space
    # deactivate takes it away; a script (not interactive) gets none
    assert _bash(f"source {activate}\ndeactivate\ncomplete -p ros2", True, _new_terminal()) == ""
    assert _bash(f"source {activate}\ncomplete -p ros2", False, _new_terminal()) == ""


@needs_bash
def test_a_workspace_setup_file_registers_completion():
    """A workspace's install/setup.bash sources this environment's setup.bash (colcon's chain,
    tests/test_workspace.py): in a new terminal, and in one started from an activated shell."""
    setup = Path(sys.prefix) / "setup.bash"
    shown = _bash(f"source {setup}\ncomplete -p ros2", True, _new_terminal())
    assert "_python_argcomplete ros2" in shown
    activated = dict(_new_terminal(), VIRTUAL_ENV=sys.prefix)  # inherited, not the shell's
    assert "_python_argcomplete ros2" in _bash(f"source {setup}\ncomplete -p ros2", True, activated)


@pytest.mark.parametrize("point", ["abc", "", "3.5", "-5", "\u0663", "99999"])
@pytest.mark.parametrize("line", ["ros2 topic li", "ros2 launch tur", "rostopic li"])
def test_a_malformed_cursor_position_completes_nothing_quietly(line, point):
    """COMP_POINT not a position within the line (argcomplete's int() raised its
    traceback; '-5' and '٣' completed the wrong word): nothing offered, nothing printed."""
    environment = {
        **os.environ,
        "_ARGCOMPLETE": "1",
        "_ARGCOMPLETE_IFS": "\n",
        "COMP_LINE": line,
        "COMP_POINT": point,
        COMPLETION_BUDGET_VARIABLE: str(TIMEOUT),
    }
    with tempfile.NamedTemporaryFile("r") as answer:
        environment["_ARGCOMPLETE_STDOUT_FILENAME"] = answer.name
        result = subprocess.run(
            [str(BIN / line.split()[0])],
            env=environment,
            stdin=subprocess.DEVNULL,
            capture_output=True,
            text=True,
            timeout=TIMEOUT,
        )
        offered_words = answer.read()
    assert result.returncode == 1 and result.stderr == "" and result.stdout == ""
    assert offered_words == ""
