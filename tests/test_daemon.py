"""`ros2 daemon start|stop|status` and the lists it answers (ros2cmd/daemon/).

The suite's lists discover for themselves (tests/conftest.py sets ROS_TUTORIALS_NO_DAEMON);
these tests run `ros2` without it, so lists go through the daemon as a learner's do. The
daemon is the session's (its socket is named from the session's private domain id); each test
stops it at its end, and conftest stops any left at the session's end.
"""

from __future__ import annotations

import os
import shutil
import time
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

import pytest
from helpers import TIMEOUT, ready, run

from ros2cmd.daemon import client as daemon

T = TypeVar("T")


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env.pop(daemon.NO_DAEMON_VARIABLE)
    return env


def ros2(*args: str) -> str:
    """`ros2 ARGS` as a learner runs it (the daemon in use): must succeed; its output."""
    result = run("ros2", *args, env=_env())
    assert result.returncode == 0, f"ros2 {' '.join(args)} failed:\n{result.stderr}"
    assert "Traceback" not in result.stderr
    return result.stdout


def _environ(pid: int) -> dict[str, str]:
    with open(f"/proc/{pid}/environ", "rb") as environ:
        entries = [entry.decode() for entry in environ.read().split(b"\0") if entry]
    return dict(entry.split("=", 1) for entry in entries)


@pytest.fixture
def running_daemon(ros_domain):
    """The session's daemon, started by `ros2 daemon start`; stopped after the test."""
    assert ros2("daemon", "start") == "The daemon has been started\n"
    try:
        yield daemon.running_pid()
    finally:
        daemon.stop_quietly()


def _eventually(condition: Callable[[], T | None], what: str) -> T:
    """condition()'s first truthy value, asked again and again for up to TIMEOUT seconds."""
    deadline = time.monotonic() + TIMEOUT
    while not (value := condition()):
        if time.monotonic() > deadline:
            pytest.fail(f"not seen within {TIMEOUT:.0f} s: {what}")
        time.sleep(0.1)  # the daemon answers after its own wait: this only paces the asking
    return value


def _answer(showing: Callable[[daemon.DaemonAnswer], bool] = lambda _: True) -> daemon.DaemonAnswer:
    """The daemon's complete answer, once it shows what `showing` looks for (the daemon may
    decline while the graph still holds a process that ended, e.g. the previous test's)."""

    def complete() -> daemon.DaemonAnswer | None:
        answer = daemon.ask_graph()
        return answer if answer is not None and showing(answer) else None

    return _eventually(complete, "a complete answer from the daemon")


def test_start_status_stop_say_what_ros2cli_says(ros_domain):
    assert ros2("daemon", "status") == "The daemon is not running\n"
    assert ros2("daemon", "stop") == "The daemon is not running\n"
    assert ros2("daemon", "start") == "The daemon has been started\n"
    try:
        pid = daemon.running_pid()
        assert pid is not None
        assert ros2("daemon", "start") == "The daemon is already running\n"
        assert ros2("daemon", "status") == "The daemon is running\n"
        # Rule 1 and the session's own domain: the daemon's participant is where ours are.
        environ = _environ(pid)
        assert environ["ROS_DOMAIN_ID"] == str(ros_domain)
        assert environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "LOCALHOST"
        assert ros2("daemon", "stop") == "The daemon has been stopped\n"
        assert not Path(f"/proc/{pid}").exists() or "Z" in Path(f"/proc/{pid}/stat").read_text()
        assert ros2("daemon", "status") == "The daemon is not running\n"
    finally:
        daemon.stop_quietly()


def test_the_daemon_is_found_with_its_runtime_folder_removed(ros_domain, tmp_path):
    """A daemon is found by its socket's name, not by a file: with the runtime folder gone
    (its socket file was there), status and start still see it and stop ends its process."""
    runtime = tmp_path / "run"
    runtime.mkdir(mode=0o700)
    env = {**_env(), "XDG_RUNTIME_DIR": str(runtime), "TMPDIR": str(runtime)}

    def ros2_here(*args: str) -> str:
        result = run("ros2", *args, env=env)
        assert result.returncode == 0 and "Traceback" not in result.stderr, result.stderr
        return result.stdout

    assert ros2_here("daemon", "start") == "The daemon has been started\n"
    try:
        pid = daemon.running_pid()
        assert pid is not None
        shutil.rmtree(runtime)
        assert ros2_here("daemon", "status") == "The daemon is running\n"
        assert ros2_here("daemon", "start") == "The daemon is already running\n"
        assert ros2_here("daemon", "stop") == "The daemon has been stopped\n"
        assert not Path(f"/proc/{pid}").exists() or "Z" in Path(f"/proc/{pid}/stat").read_text()
        assert ros2_here("daemon", "status") == "The daemon is not running\n"
    finally:
        daemon.stop_quietly()


def test_daemon_without_a_command_prints_usage(ros_domain):
    result = run("ros2", "daemon", "restart", env=_env())
    assert result.returncode == 2
    assert "usage:" in result.stderr and "Traceback" not in result.stderr


def test_a_list_starts_the_daemon_and_answers_itself(ros_domain, node_process):
    node_process("-m", "ros_tutorials_topic.publisher")
    try:
        # No daemon yet: the list discovers for itself (complete) and starts one.
        assert "/topic_publisher\n" in ros2("node", "list")
        assert _eventually(daemon.running_pid, "a daemon") is not None
    finally:
        daemon.stop_quietly()


def test_a_list_through_the_daemon_sees_a_node_started_after_it(running_daemon, node_process):
    before = _answer()
    assert "/topic_publisher" not in before.node_names()
    publisher = node_process("-m", "ros_tutorials_topic.publisher")
    publisher.wait_for_text("send msg")
    # Asked right away: the daemon waits until it has heard from the new process; any
    # answer it gives as complete holds the node (it may decline on a very busy machine).
    for _ in range(3):
        answer = daemon.ask_graph()
        assert answer is None or "/topic_publisher" in answer.node_names()
    answer = _answer()
    assert "/topic_publisher" in answer.node_names()
    assert "/ros_tutorial_msg" in answer.topic_types()
    assert "/topic_publisher\n" in ros2("node", "list")


def test_a_node_that_ended_is_not_listed(running_daemon, node_process):
    publisher = node_process("-m", "ros_tutorials_topic.publisher")
    publisher.wait_for_text("send msg")
    assert "/topic_publisher" in _answer().node_names()
    publisher.kill()  # SIGKILL: DDS keeps its participant until the lease runs out
    assert "/topic_publisher" not in ros2("node", "list")
    # The daemon declined (its graph still holds the dead participant) or knows it is gone.
    answer = daemon.ask_graph()
    assert answer is None or "/topic_publisher" not in answer.node_names()


def test_lists_with_the_daemon_equal_lists_without(running_daemon, node_process):
    ready(node_process("-m", "ros_tutorials_service.server"))
    node_process("-m", "ros_tutorials_topic.publisher").wait_for_text("send msg")
    node_process("-m", "ros_tutorials_action.server")
    _answer(lambda answer: "/ros_tutorial_action" in answer.action_types())
    for command in (
        ("node", "list"),
        ("topic", "list", "-t"),
        ("service", "list", "-t"),
        ("action", "list", "-t"),
        ("topic", "find", "std_msgs/msg/String"),
        ("node", "info", "/topic_publisher"),
        ("node", "info", "/action_server", "--include-hidden"),
        ("topic", "info", "/ros_tutorial_msg"),
        ("topic", "type", "/ros_tutorial_msg"),
        ("service", "type", "/ros_tutorial_srv"),
    ):
        assert daemon.ask_graph() is not None, "the daemon must answer for this comparison"
        through_daemon = ros2(*command)
        direct = ros2(*command, "--no-daemon")
        assert through_daemon == direct, command
    assert "/ros_tutorial_srv [ros_tutorials_interfaces/srv/SrvTutorial]\n" in ros2(
        "service", "list", "-t"
    )


SQUATTER = """
import socket, sys
s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
s.bind(sys.argv[1].encode("latin-1").replace(b"@", b"\\0", 1))
if sys.argv[2] == "listen":
    s.listen(1)
print("bound", flush=True)
sys.stdin.read()
"""


@pytest.mark.skipif(
    os.getuid() != 0 or not shutil.which("setpriv"), reason="needs root to run as nobody"
)
@pytest.mark.parametrize("listening", ["listen", "bind only"])
def test_the_daemons_name_taken_by_another_user_is_said_with_who(ros_domain, listening):
    """Another user's process binds this user's daemon name first (an abstract socket has
    no permissions): start says so at once, and status after its line, naming that user
    and process (before: start waited 10 s for `did not start`, status only `not running`)."""
    import subprocess

    address = "@" + daemon.socket_address()[1:]
    squatter = subprocess.Popen(
        [
            "setpriv",
            "--reuid=65534",
            "--regid=65534",
            "--clear-groups",
            "/usr/bin/python3",
            "-c",
            SQUATTER,
            address,
            listening,
        ],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        text=True,
        cwd="/",
    )
    try:
        assert squatter.stdout.readline() == "bound\n"
        held = (
            "another user's process holds this daemon's name (uid 65534 (nobody), pid "
            f"{squatter.pid} (python3)), so no daemon of yours can start with these DDS "
            "settings; the lists discover for themselves"
        )
        started = time.monotonic()
        result = run("ros2", "daemon", "start", env=_env())
        assert (result.returncode, result.stdout, result.stderr) == (1, "", f"error: {held}\n")
        assert time.monotonic() - started < daemon.START_TIMEOUT  # not its whole wait
        result = run("ros2", "daemon", "status", env=_env())
        assert (result.returncode, result.stdout, result.stderr) == (
            0,
            "The daemon is not running\n",
            f"warning: {held}\n",
        )
    finally:
        squatter.kill()
        squatter.wait()
