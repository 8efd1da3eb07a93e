"""The lesson files travel: each, copied unchanged into a package of one's own (`ros2 pkg
create`, the real colcon, `source install/setup.bash`), runs with `ros2 run` against this
project's own counterpart and prints the lesson's lines.

One workspace is built for the whole module (and shared by the pytest-xdist processes: the
first builds it, the others wait for it); each test then runs the lessons of one package.
"""

from __future__ import annotations

import fcntl
import os
import shlex
import shutil
from collections.abc import Iterator
from pathlib import Path

import pytest
from helpers import NodeProcess
from test_workspace import BUILD_TIMEOUT, activated, add_entry_points, learner_environment, ok

ROOT = Path(__file__).resolve().parent.parent
LESSONS = ("topic", "service", "parameter", "action")
# ros2/demos' nodes keep their names (introspection.py imports the two beside it).
DEMOS = "demo_nodes"
TIMEOUT = 60.0
pytestmark = pytest.mark.long


def copied_name(package: str, path: Path) -> str:
    """The module name a lesson file gets in my_lessons: topic_publisher, service_client, ..."""
    return path.stem if package == DEMOS else f"{package}_{path.stem}"


def lesson_files() -> dict[str, Path]:
    found = {}
    for package in (*LESSONS, DEMOS):
        for path in sorted((ROOT / f"ros_tutorials_{package}").glob("*.py")):
            if path.name != "__init__.py":
                found[copied_name(package, path)] = path
    return found


def build(workspace: Path) -> None:
    """The learner's steps: the package, the lesson files copied as they are, setup.py's
    console_scripts, colcon build."""
    (workspace / "src").mkdir(parents=True)
    depends = "rclpy ros_tutorials_interfaces std_msgs example_interfaces rcl_interfaces"
    ok(
        activated(f"ros2 pkg create --build-type ament_python my_lessons --dependencies {depends}"),
        workspace / "src",
    )
    package = workspace / "src" / "my_lessons"
    for name, path in lesson_files().items():
        shutil.copyfile(path, package / "my_lessons" / f"{name}.py")
    entries = [f"{name} = my_lessons.{name}:main" for name in lesson_files()]
    add_entry_points(package / "setup.py", *entries)
    built = ok(activated("colcon build"), workspace, BUILD_TIMEOUT)
    assert "Summary: 1 package finished" in built, built


@pytest.fixture(scope="module")
def workspace(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    """The built workspace, one for all pytest processes of this run."""
    shared = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        shared = shared.parent  # the run's folder, above each process's own
    workspace = shared / "take_home_ws"
    with open(shared / "take_home_ws.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # held while one process builds
        if not (workspace / "install" / "setup.bash").exists():
            shutil.rmtree(workspace, ignore_errors=True)
            build(workspace)
    yield workspace


@pytest.fixture
def terminal(workspace: Path) -> Iterator:
    """terminal(command): COMMAND run in a new terminal where the workspace was sourced."""
    started: list[NodeProcess] = []

    def start(command: str) -> NodeProcess:
        script = f"cd {shlex.quote(str(workspace))} && source install/setup.bash && exec {command}"
        variables = [f"{name}={value}" for name, value in learner_environment().items()]
        # NodeProcess appends its interpreter's path: the script's $1, unused.
        process = NodeProcess(prefix=["env", "-i", *variables, "bash", "-c", script, "bash"])
        started.append(process)
        return process

    yield start
    for process in started:
        process.kill()


def test_every_lesson_file_is_in_the_package(workspace):
    listed = ok(f"cd {workspace} && source install/setup.bash && ros2 pkg executables my_lessons",
                workspace)  # fmt: skip
    assert sorted(listed.splitlines()) == sorted(f"my_lessons {name}" for name in lesson_files())


def exchange(terminal, mine: str, mine_says: str, theirs: str, theirs_says: str) -> None:
    """`ros2 run my_lessons MINE` and `ros2 run THEIRS` (this project's) side by side: each
    prints its line; a client then ends by itself, a node that spins at Ctrl-C; both with
    exit status 0."""
    copied = terminal(f"ros2 run my_lessons {mine}")
    project = terminal(f"ros2 run {theirs}")
    for process, text, other in ((copied, mine_says, project), (project, theirs_says, copied)):
        if text:  # the Num publisher logs nothing
            try:
                process.wait_for_text(text, timeout=TIMEOUT)
            except pytest.fail.Exception as failed:  # what the other side said, too
                pytest.fail(f"{failed}\nthe other side's output was:\n{other.output}")
    for process, command in ((copied, mine), (project, theirs)):
        one_shot = "client" in command and "introspection" not in command
        status = process.wait() if one_shot else process.interrupt()
        assert status == 0, process.output
        assert "Traceback" not in process.output


@pytest.mark.parametrize(
    ("mine", "mine_says", "theirs", "theirs_says"),
    [
        ("topic_publisher", "send msg = ", "ros_tutorials_topic topic_subscriber",
         "recieve msg = "),
        ("topic_subscriber", "recieve msg = ", "ros_tutorials_topic topic_publisher",
         "send msg = "),
        ("topic_talker", "hello world", "ros_tutorials_topic listener", "I heard: [hello world"),
        ("topic_listener", "I heard: [hello world", "ros_tutorials_topic talker", "hello world"),
        ("topic_aandb_talker", "msg a: 1.000000, msg b:2.000000",
         "ros_tutorials_topic aandb_listener", "I heard: msg:a 1.000000, msg:b 2.000000"),
        ("topic_aandb_listener", "I heard: msg:a 1.000000, msg:b 2.000000",
         "ros_tutorials_topic aandb_talker", "msg a: 1.000000"),
        ("topic_num_publisher", "", "ros_tutorials_topic num_subscriber", "I heard: ["),
        ("topic_num_subscriber", "I heard: [", "ros_tutorials_topic num_publisher", ""),
        ("topic_user_record_publisher", "first_name: Ada, last_name: Lovelace",
         "ros_tutorials_topic user_record_subscriber", "Receive : Ada Lovelace, age 36"),
        ("topic_user_record_subscriber", "Receive : Ada Lovelace, age 36",
         "ros_tutorials_topic user_record_publisher", "first_name: Ada"),
        ("topic_workshop_talker", "[talker]: hello world",
         "ros_tutorials_topic workshop_listener", "/listenerReceive : hello world"),
        ("topic_workshop_listener", "/listenerReceive : hello world",
         "ros_tutorials_topic workshop_talker", "[talker]: hello world"),
    ],
)  # fmt: skip
def test_topic_lessons(terminal, mine, mine_says, theirs, theirs_says):
    exchange(terminal, mine, mine_says, theirs, theirs_says)


@pytest.mark.parametrize(
    ("mine", "mine_says", "theirs", "theirs_says"),
    [
        ("service_server", "sending back response: 5",
         "ros_tutorials_service service_client 2 3 --timeout 60",
         "receive srv, srv.Response.result: 5"),
        ("service_client 2 3 --timeout 60", "receive srv, srv.Response.result: 5",
         "ros_tutorials_service service_server", "sending back response: 5"),
        ("service_add_two_ints_server", "sending back response: [3]",
         "ros_tutorials_service add_two_ints_client 1 2 --timeout 60", "Sum: 3"),
        ("service_add_two_ints_client 1 2 --timeout 60", "Sum: 3",
         "ros_tutorials_service add_two_ints_server", "sending back response: [3]"),
        ("service_workshop_add_two_ints_server", "Returning [1 + 2 = 3]",
         "ros_tutorials_service workshop_add_two_ints_client 1 2", "1 + 2 = 3"),
        ("service_workshop_add_two_ints_client 1 2", "1 + 2 = 3",
         "ros_tutorials_service workshop_add_two_ints_server", "Returning [1 + 2 = 3]"),
        ("parameter_server --ros-args -p calculation_method:=3", "sending back response: [50]",
         "ros_tutorials_parameter service_client_with_parameter 10 5 --timeout 60",
         "receive srv, srv.Response.result: 50"),
        ("parameter_client 10 5 --timeout 60", "receive srv, srv.Response.result: 15",
         "ros_tutorials_parameter service_server_with_parameter", "sending back response: [15]"),
        ("parameter_talker --ros-args -p talker_str:=Goodbye", "Goodbye",
         "ros_tutorials_topic listener", "I heard: [Goodbye]"),
    ],
)  # fmt: skip
def test_service_and_parameter_lessons(terminal, mine, mine_says, theirs, theirs_says):
    exchange(terminal, mine, mine_says, theirs, theirs_says)


@pytest.mark.parametrize(
    ("mine", "theirs"),
    [
        ("action_server --ros-args -p step_period:=0.05",
         "ros_tutorials_action action_client 3 --timeout 60"),
        ("action_client 3 --timeout 60",
         "ros_tutorials_action action_server --ros-args -p step_period:=0.05"),
    ],
)  # fmt: skip
def test_action_lessons(terminal, mine, theirs):
    server_says, client_says = "ros_tutorial_action: Succeeded", "Action finished: SUCCEEDED"
    mine_says, theirs_says = (
        (server_says, client_says) if mine.startswith("action_server") else
        (client_says, server_says)
    )  # fmt: skip
    exchange(terminal, mine, mine_says, theirs, theirs_says)


@pytest.mark.parametrize(
    ("mine", "mine_says", "theirs", "theirs_says"),
    [
        ("talker", "Publishing: 'Hello World: 1'", "demo_nodes_py listener",
         "I heard: [Hello World: "),
        ("listener", "I heard: [Hello World: ", "demo_nodes_cpp talker",
         "Publishing: 'Hello World: 1'"),
        ("introspection_service", "Incoming request", "demo_nodes_cpp introspection_client",
         "Result of add_two_ints: 5"),
        ("introspection_client", "Result of add_two_ints: 5",
         "demo_nodes_cpp introspection_service", "Incoming request"),
    ],
)  # fmt: skip
def test_demo_nodes(terminal, mine, mine_says, theirs, theirs_says):
    exchange(terminal, mine, mine_says, theirs, theirs_says)


def test_introspection_runs_both_nodes_from_the_files_beside_it(terminal):
    both = terminal("ros2 run my_lessons introspection")
    both.wait_for_text("Result of add_two_ints: 5", timeout=TIMEOUT)
    assert both.interrupt() == 0, both.output
