"""The learner's own packages, as the official Jazzy tutorials build them: `ros2 pkg create`,
the real colcon, `source install/setup.bash`, then `ros2 run` and the other tools
("Creating your first ROS 2 package", "Writing a simple publisher and subscriber (Python)",
"Creating custom msg and srv files").

Each test makes a workspace in a temporary folder and types the pages' commands in bash, as
a learner does in a terminal: the build after `source .venv/bin/activate` (what `source
/opt/ros/jazzy/setup.bash` is elsewhere), the rest in a new shell that only sources the
workspace's install/setup.bash. The pages' code is in tests/data/workspace/, as printed.
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import NodeProcess

DATA = Path(__file__).parent / "data" / "workspace"
ACTIVATE = Path(sys.prefix) / "bin" / "activate"
BUILD_TIMEOUT = 600.0  # a colcon build of an interface package on a loaded 2-core machine
TIMEOUT = 60.0


def learner_environment() -> dict[str, str]:
    """A new terminal's environment: nothing of this environment activated, this test
    session's ROS domain (tests/conftest.py) and log folder kept."""
    env = {"PATH": "/usr/local/bin:/usr/bin:/bin", "HOME": os.environ.get("HOME", "/tmp")}
    for name in ("ROS_DOMAIN_ID", "ROS_LOG_DIR", "ROS_HOME", "LANG", "TMPDIR"):
        if name in os.environ:
            env[name] = os.environ[name]
    return env


def bash(script: str, cwd: Path, timeout: float = TIMEOUT) -> subprocess.CompletedProcess:
    """Run SCRIPT in a new bash in CWD; fails the test if it does not end within timeout."""
    try:
        return subprocess.run(
            ["bash", "-c", script],
            cwd=cwd,
            env=learner_environment(),
            capture_output=True,
            text=True,
            timeout=timeout,
        )
    except subprocess.TimeoutExpired as error:
        pytest.fail(f"{script!r} did not finish within {timeout:.0f} s: {error.stdout!r}")


def ok(script: str, cwd: Path, timeout: float = TIMEOUT) -> str:
    result = bash(script, cwd, timeout)
    assert result.returncode == 0, f"{script} failed:\n{result.stdout}\n{result.stderr}"
    assert "Traceback" not in result.stderr, result.stderr
    return result.stdout


def activated(script: str) -> str:
    return f". {shlex.quote(str(ACTIVATE))}\n{script}"


def sourced(script: str) -> str:
    return f"source install/setup.bash\n{script}"


def colcon_build(workspace: Path, *args: str) -> str:
    return ok(activated(f"colcon build {' '.join(args)}"), workspace, BUILD_TIMEOUT)


def new_workspace(tmp_path: Path) -> Path:
    workspace = tmp_path / "ros2_ws"
    (workspace / "src").mkdir(parents=True)
    return workspace


def create(workspace: Path, arguments: str) -> str:
    return ok(activated(f"ros2 pkg create {arguments}"), workspace / "src")


def add_line_after(path: Path, anchor: str, line: str) -> None:
    """Add LINE after the first line containing ANCHOR, as the learner edits the file."""
    text = path.read_text()
    at = text.index("\n", text.index(anchor)) + 1
    path.write_text(text[:at] + line + "\n" + text[at:])


def add_entry_points(setup_py: Path, *entries: str) -> None:
    """The page's `entry_points` edit of setup.py: lines within the console_scripts brackets."""
    text = setup_py.read_text()
    lines = "".join(f"\n            '{entry}'," for entry in entries)
    new = re.sub(r"'console_scripts': \[\n", lambda m: m.group(0) + lines[1:] + "\n", text)
    assert new != text
    setup_py.write_text(new)


def test_first_package_ament_python_builds_and_runs(tmp_path):
    """Creating-Your-First-ROS2-Package: ament_python with --node-name, colcon build, then
    `ros2 run my_package my_node` prints "Hi from my_package." and the tools find it."""
    workspace = new_workspace(tmp_path)
    create(
        workspace, "--build-type ament_python --license Apache-2.0 --node-name my_node my_package"
    )
    built = colcon_build(workspace)
    assert "Summary: 1 package finished" in built
    # The template's setup.py (tests_require) builds without a warning, as on Jazzy.
    assert "stderr output" not in built, built
    assert ok(sourced("ros2 run my_package my_node"), workspace) == "Hi from my_package.\n"
    prefix = workspace / "install" / "my_package"
    listed = ok(sourced("ros2 pkg list"), workspace).splitlines()
    assert "my_package" in listed and "std_msgs" in listed
    assert ok(sourced("ros2 pkg prefix my_package"), workspace) == f"{prefix}\n"
    assert ok(sourced("ros2 pkg executables my_package"), workspace) == "my_package my_node\n"
    # rosrun finds it the same way, and the node runs by hand too, as colcon installed it.
    assert ok(sourced("rosrun my_package my_node"), workspace) == "Hi from my_package.\n"
    node = "install/my_package/lib/my_package/my_node"
    assert ok(sourced(node), workspace) == "Hi from my_package.\n"


def test_a_learners_package_is_built_with_jazzys_setuptools():
    """colcon runs an ament_python package's setup.py with this environment's Python, so its
    setuptools is the learner's: ROS 2 Jazzy's (Ubuntu 24.04's 68), whatever the Python. Since
    72, setuptools no longer knows the template's `tests_require` (a warning on each build, and
    `colcon test` finds no pytest tests); a 3.12 venv would get the newest."""
    shown = ok(activated("python -c 'import setuptools; print(setuptools.__version__)'"), DATA)
    assert shown == "68.1.2\n"


def test_a_package_built_but_not_sourced_says_source_install_setup_bash(tmp_path):
    workspace = new_workspace(tmp_path)
    create(workspace, "--build-type ament_python --node-name my_node my_package")
    colcon_build(workspace)
    for command in ("ros2 run my_package my_node", "rosrun my_package my_node"):
        result = bash(activated(command), workspace)
        assert result.returncode == 1 and result.stdout == ""
        assert result.stderr.count("\n") == 1, result.stderr
        assert "run `source install/setup.bash`" in result.stderr


def test_ros2_pkg_create_refuses_a_bad_name_and_an_existing_package(tmp_path):
    workspace = new_workspace(tmp_path)
    result = bash(activated("ros2 pkg create My-Package"), workspace / "src")
    assert result.returncode == 1 and result.stdout == ""
    assert result.stderr == (
        "error: 'My-Package' is not a valid package name: lower-case letters, digits and "
        "underscores, starting with a letter (REP 144), e.g. my_package\n"
    )
    create(workspace, "my_package")
    result = bash(activated("ros2 pkg create my_package"), workspace / "src")
    assert result.returncode == 1 and result.stderr.count("\n") == 1
    assert "The directory already exists: ./my_package" in result.stderr


def test_the_environment_a_sourced_workspace_gives_its_nodes(tmp_path):
    """install/setup.bash in a new terminal activates the environment it was built in (as it
    sources /opt/ros/jazzy elsewhere): DDS stays on this machine, the index has both."""
    workspace = new_workspace(tmp_path)
    create(workspace, "--build-type ament_python --node-name my_node my_package")
    colcon_build(workspace)
    shown = ok(
        sourced("printenv ROS_AUTOMATIC_DISCOVERY_RANGE AMENT_PREFIX_PATH ROS_DISTRO"), workspace
    )
    assert shown.splitlines() == [
        "LOCALHOST",
        f"{workspace / 'install' / 'my_package'}:{sys.prefix}",
        "jazzy",
    ]
    # The user's own setting stays.
    script = sourced("printenv ROS_AUTOMATIC_DISCOVERY_RANGE")
    assert ok(f"export ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET\n{script}", workspace) == "SUBNET\n"


def terminal(workspace: Path, command: str) -> NodeProcess:
    """COMMAND running in a new terminal in which the workspace was sourced."""
    script = f"cd {shlex.quote(str(workspace))} && {sourced(f'exec {command}')}"
    variables = [f"{name}={value}" for name, value in learner_environment().items()]
    # NodeProcess appends its interpreter's path: the script's $1, unused.
    return NodeProcess(prefix=["env", "-i", *variables, "bash", "-c", script, "bash"])


def talker_and_listener(workspace: Path, package: str, heard: str) -> None:
    """`ros2 run PACKAGE talker` and `ros2 run PACKAGE listener` in two terminals: the
    listener prints what the talker publishes."""
    talker = terminal(workspace, f"ros2 run {package} talker")
    listener = terminal(workspace, f"ros2 run {package} listener")
    try:
        talker.wait_for_text("Publishing: ", timeout=TIMEOUT)
        listener.wait_for_text(heard, timeout=TIMEOUT)
    finally:
        talker.kill()
        listener.kill()


def py_pubsub(workspace: Path, publisher: str, subscriber: str, *depends: str) -> None:
    """The page's py_pubsub: `ros2 pkg create`, the two files, package.xml and setup.py."""
    create(workspace, "--build-type ament_python --license Apache-2.0 py_pubsub")
    package = workspace / "src" / "py_pubsub"
    (package / "py_pubsub" / "publisher_member_function.py").write_text(
        (DATA / publisher).read_text()
    )
    (package / "py_pubsub" / "subscriber_member_function.py").write_text(
        (DATA / subscriber).read_text()
    )
    for depend in reversed(depends):
        add_line_after(
            package / "package.xml", "<license>", f"  <exec_depend>{depend}</exec_depend>"
        )
    add_entry_points(
        package / "setup.py",
        "talker = py_pubsub.publisher_member_function:main",
        "listener = py_pubsub.subscriber_member_function:main",
    )


def test_simple_py_publisher_and_subscriber(tmp_path):
    """Writing-A-Simple-Py-Publisher-And-Subscriber: the page's code, `colcon build
    --packages-select py_pubsub`, talker and listener in two terminals."""
    workspace = new_workspace(tmp_path)
    py_pubsub(
        workspace,
        "publisher_member_function.py",
        "subscriber_member_function.py",
        "rclpy",
        "std_msgs",
    )
    colcon_build(workspace, "--packages-select py_pubsub")
    talker_and_listener(workspace, "py_pubsub", 'I heard: "Hello World: ')


# Custom-ROS2-Interfaces: the files of tutorial_interfaces and the lines the page adds to
# CMakeLists.txt and package.xml (in tests/data/workspace/, as printed).
INTERFACE_FILES = {
    "msg/Num.msg": "int64 num\n",
    "msg/Sphere.msg": "geometry_msgs/Point center\nfloat64 radius\n",
    "srv/AddThreeInts.srv": "int64 a\nint64 b\nint64 c\n---\nint64 sum\n",
}
CMAKE_LINES = (DATA / "tutorial_interfaces_CMakeLists.txt").read_text()
PACKAGE_XML_LINES = (DATA / "tutorial_interfaces_package.xml").read_text().rstrip("\n")
# What `ros2 interface show` prints, as the page shows it.
SHOWN = {
    "tutorial_interfaces/msg/Num": "int64 num\n",
    "tutorial_interfaces/msg/Sphere": (
        "geometry_msgs/Point center\n\tfloat64 x\n\tfloat64 y\n\tfloat64 z\nfloat64 radius\n"
    ),
    "tutorial_interfaces/srv/AddThreeInts": "int64 a\nint64 b\nint64 c\n---\nint64 sum\n",
}


def tutorial_interfaces(workspace: Path) -> Path:
    create(workspace, "--build-type ament_cmake --license Apache-2.0 tutorial_interfaces")
    package = workspace / "src" / "tutorial_interfaces"
    for name, text in INTERFACE_FILES.items():
        (package / name).parent.mkdir(exist_ok=True)
        (package / name).write_text(text)
    add_line_after(package / "CMakeLists.txt", "find_package(ament_cmake REQUIRED)", CMAKE_LINES)
    add_line_after(package / "package.xml", "<license>", PACKAGE_XML_LINES)
    return package


def test_custom_interfaces_build_show_and_carry_messages(tmp_path):
    """Custom-ROS2-Interfaces: tutorial_interfaces with the page's lines only, built by
    `colcon build --packages-select tutorial_interfaces`; `ros2 interface show` prints what
    the page shows; the page's Num publisher and subscriber talk."""
    workspace = new_workspace(tmp_path)
    tutorial_interfaces(workspace)
    colcon_build(workspace, "--packages-select tutorial_interfaces")
    for name, text in SHOWN.items():
        assert ok(sourced(f"ros2 interface show {name}"), workspace) == text
    py_pubsub(
        workspace,
        "num_publisher_member_function.py",
        "num_subscriber_member_function.py",
        "rclpy",
        "tutorial_interfaces",
    )
    colcon_build(workspace, "--packages-select py_pubsub")
    talker_and_listener(workspace, "py_pubsub", 'I heard: "')


@pytest.mark.long  # a C++ compile
def test_first_package_ament_cmake_builds_and_runs(tmp_path):
    """Creating-Your-First-ROS2-Package, the CMake tab: its C++ node, compiled, runs."""
    workspace = new_workspace(tmp_path)
    create(
        workspace, "--build-type ament_cmake --license Apache-2.0 --node-name my_node my_package"
    )
    colcon_build(workspace)
    shown = ok(sourced("ros2 run my_package my_node"), workspace)
    assert shown == "hello world my_package package\n"


def failure_lines(result: subprocess.CompletedProcess) -> list[str]:
    """A failed `colcon build`: its `error:` lines; colcon's own report, without the
    package's stderr (ros_tutorials_common/colcon_events.py) and without a traceback."""
    assert result.returncode != 0, result.stdout + result.stderr
    assert "Traceback" not in result.stdout + result.stderr, result.stderr
    assert "--- stderr:" not in result.stderr, result.stderr
    return [line for line in result.stderr.splitlines() if line.startswith("error: ")]


def full_log(line: str, workspace: Path) -> str:
    """The text of the log an error line names."""
    match = re.search(r" \(full log: (log/build_[-_0-9]+/\w+/stdout_stderr\.log)\)$", line)
    assert match, line
    return (workspace / match.group(1)).read_text()


@pytest.mark.long  # an interface build, then two that fail early
def test_a_failing_interface_build_says_where_and_leaves_the_last_good_install(tmp_path):
    """A syntax error in a .msg, then a type of a package the CMakeLists.txt does not name:
    each build fails with one line naming the file, the line and the reason, and the log;
    what was installed before still works."""
    workspace = new_workspace(tmp_path)
    package = tutorial_interfaces(workspace)
    colcon_build(workspace)
    (package / "msg" / "Num.msg").write_text("# a number\nint64 num num\n")
    result = bash(activated("colcon build"), workspace, BUILD_TIMEOUT)
    [line] = failure_lines(result)
    assert line.startswith(
        "error: tutorial_interfaces: src/tutorial_interfaces/msg/Num.msg:2: 'int64 num num': "
        "value 'num' can not be converted to type 'int64'"
    ), line
    # colcon's and rosidl's own report is in the log the line names.
    assert "Error processing 'int64 num num' of 'tutorial_interfaces/Num'" in full_log(
        line, workspace
    )
    assert "Failed   <<< tutorial_interfaces" in result.stderr
    assert "1 package failed: tutorial_interfaces" in result.stdout

    (package / "msg" / "Num.msg").write_text("int64 num\nsensor_msgs/Temperature t\n")
    [line] = failure_lines(bash(activated("colcon build"), workspace, BUILD_TIMEOUT))
    assert line.startswith(
        "error: tutorial_interfaces: src/tutorial_interfaces/msg/Num.msg:2: uses a type of "
        "package 'sensor_msgs', which is not in rosidl_generate_interfaces' "
        "DEPENDENCIES"
    ), line
    assert (
        ok(sourced("ros2 interface show tutorial_interfaces/msg/Num"), workspace) == "int64 num\n"
    )


def test_a_missing_dependency_fails_in_one_line_naming_it(tmp_path):
    """`ros2 pkg create --dependencies` with a package that does not exist: the build stops
    at its find_package() line, in one line."""
    workspace = new_workspace(tmp_path)
    create(workspace, "--build-type ament_cmake my_package --dependencies no_such_msgs")
    result = bash(activated("colcon build"), workspace, BUILD_TIMEOUT)
    [line] = failure_lines(result)
    number = next(
        number
        for number, text in enumerate(
            (workspace / "src" / "my_package" / "CMakeLists.txt").read_text().splitlines(), 1
        )
        if "find_package(no_such_msgs REQUIRED)" in text
    )
    assert line.startswith(
        f"error: my_package: src/my_package/CMakeLists.txt:{number}: find_package(no_such_msgs): "
        "no package 'no_such_msgs' here"
    ), line
    assert "Could not find a package configuration file" in full_log(line, workspace)
    # console_stderr, asked for, shows colcon's whole report as on a ROS 2 installation.
    result = bash(
        activated("colcon build --event-handlers console_stderr+"), workspace, BUILD_TIMEOUT
    )
    assert result.returncode != 0 and "--- stderr: my_package" in result.stderr
    again = [line for line in result.stderr.splitlines() if line.startswith("error: ")]
    assert [text.partition(" (full log: ")[0] for text in again] == [
        line.partition(" (full log: ")[0]
    ]


def test_a_compile_error_names_the_file_and_line(tmp_path):
    """The C++ node of `ros2 pkg create --node-name`, with a typo: the compiler's first error."""
    workspace = new_workspace(tmp_path)
    create(workspace, "--build-type ament_cmake --node-name my_node my_package")
    node = workspace / "src" / "my_package" / "src" / "my_node.cpp"
    lines = node.read_text().splitlines()
    at = next(number for number, text in enumerate(lines) if "printf" in text)
    lines[at] = lines[at].replace(";", "")
    node.write_text("\n".join(lines) + "\n")
    [line] = failure_lines(bash(activated("colcon build"), workspace, BUILD_TIMEOUT))
    # The missing ';' is reported where the next statement starts.
    assert re.match(r"error: my_package: src/my_package/src/my_node\.cpp:\d+: expected ", line), (
        line
    )
    assert "my_node.cpp" in full_log(line, workspace)


SHOW_RANGE = """\
import os


def main():
    print('range:', os.environ.get('ROS_AUTOMATIC_DISCOVERY_RANGE', 'unset'))
"""
LAUNCH_FILE = """\
<launch>
  <node pkg="my_package" exec="my_node" output="screen"/>
</launch>
"""


def test_a_workspace_node_keeps_dds_on_this_machine_however_started(tmp_path):
    """`ros2 run`, `ros2 launch` (an XML launch file the package installs) and the installed
    script by hand: the node starts with ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST, even from a
    shell where it was unset after sourcing, and with the user's own value when set."""
    workspace = new_workspace(tmp_path)
    create(workspace, "--build-type ament_python --node-name my_node my_package")
    package = workspace / "src" / "my_package"
    (package / "my_package" / "my_node.py").write_text(SHOW_RANGE)
    (package / "launch").mkdir()
    (package / "launch" / "my.launch.xml").write_text(LAUNCH_FILE)
    setup_py = package / "setup.py"
    setup_py.write_text("import os\nfrom glob import glob\n" + setup_py.read_text())
    add_line_after(
        setup_py,
        "('share/' + package_name, ['package.xml']),",
        "        (os.path.join('share', package_name, 'launch'), glob('launch/*')),",
    )
    colcon_build(workspace)
    unset = "unset ROS_AUTOMATIC_DISCOVERY_RANGE; "
    assert ok(sourced(unset + "ros2 run my_package my_node"), workspace) == "range: LOCALHOST\n"
    launched = ok(sourced(unset + "ros2 launch my_package my.launch.xml"), workspace)
    assert "[my_node-1] range: LOCALHOST" in launched  # ros2 launch: EXECUTABLE-N
    by_hand = sourced("install/my_package/lib/my_package/my_node")
    assert ok(by_hand, workspace) == "range: LOCALHOST\n"
    chosen = "export ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET\n"
    assert ok(chosen + sourced("ros2 run my_package my_node"), workspace) == "range: SUBNET\n"


def test_simple_py_service_and_client(tmp_path):
    """Writing-A-Simple-Py-Service-And-Client: py_srvcli on example_interfaces (as ROS 2
    ships it); `ros2 run py_srvcli client 2 3` prints the page's result line."""
    workspace = new_workspace(tmp_path)
    create(
        workspace,
        "--build-type ament_python --license Apache-2.0 py_srvcli "
        "--dependencies rclpy example_interfaces",
    )
    package = workspace / "src" / "py_srvcli"
    for name in ("service_member_function.py", "client_member_function.py"):
        (package / "py_srvcli" / name).write_text((DATA / name).read_text())
    add_entry_points(
        package / "setup.py",
        "service = py_srvcli.service_member_function:main",
        "client = py_srvcli.client_member_function:main",
    )
    colcon_build(workspace, "--packages-select py_srvcli")
    service = terminal(workspace, "ros2 run py_srvcli service")
    try:
        result = bash(sourced("ros2 run py_srvcli client 2 3"), workspace)
        assert result.returncode == 0, result.stderr
        # rclpy's log lines go to standard error.
        assert "[minimal_client_async]: Result of add_two_ints: for 2 + 3 = 5" in result.stderr
        service.wait_for_text("[minimal_service]: Incoming request")
        service.wait_for_text("a: 2 b: 3")
    finally:
        service.kill()


ACTION_CMAKE_LINES = """\
find_package(rosidl_default_generators REQUIRED)

rosidl_generate_interfaces(${PROJECT_NAME}
  "action/Fibonacci.action"
)
"""
ACTION_PACKAGE_XML_LINES = """\
  <buildtool_depend>rosidl_default_generators</buildtool_depend>
  <member_of_group>rosidl_interface_packages</member_of_group>"""


@pytest.mark.long  # an interface build, and the page's goal takes 9 s
def test_creating_an_action_and_its_python_server_and_client(tmp_path):
    """Creating-an-Action (custom_action_interfaces, as the page builds it) and
    Writing-an-Action-Server-Client (Python): the page's server and client, each run with
    `python3 FILE` in a terminal where the workspace is sourced (install/local_setup.bash
    over the activated environment)."""
    workspace = new_workspace(tmp_path)
    create(workspace, "--license Apache-2.0 custom_action_interfaces")
    package = workspace / "src" / "custom_action_interfaces"
    (package / "action").mkdir()
    (package / "action" / "Fibonacci.action").write_text(
        "int32 order\n---\nint32[] sequence\n---\nint32[] partial_sequence\n"
    )
    cmakelists = package / "CMakeLists.txt"
    text = cmakelists.read_text()
    cmakelists.write_text(text.replace("ament_package()", ACTION_CMAKE_LINES + "\nament_package()"))
    add_line_after(package / "package.xml", "<license>", ACTION_PACKAGE_XML_LINES)
    colcon_build(workspace)
    local = "source install/local_setup.bash\n"
    shown = ok(
        activated(local + "ros2 interface show custom_action_interfaces/action/Fibonacci"),
        workspace,
    )
    assert shown == "int32 order\n---\nint32[] sequence\n---\nint32[] partial_sequence\n"
    for name in ("fibonacci_action_server.py", "fibonacci_action_client.py"):
        (workspace / name).write_text((DATA / name).read_text())
    server = terminal(workspace, "python3 fibonacci_action_server.py")
    client = terminal(workspace, "python3 fibonacci_action_client.py")
    try:
        client.wait_for_text("[fibonacci_action_client]: Goal accepted :)")
        server.wait_for_text("[fibonacci_action_server]: Executing goal...")
        client.wait_for_text("Received feedback: array('i', [0, 1, 1])")
        result = "Result: array('i', [0, 1, 1, 2, 3, 5, 8, 13, 21, 34, 55])"
        client.wait_for_text(f"[fibonacci_action_client]: {result}", timeout=2 * TIMEOUT)
    finally:
        server.kill()
        client.kill()


def test_using_parameters_in_a_class_python(tmp_path):
    """Using-Parameters-In-A-Class-Python: the node says "Hello world!" each second, and
    "Hello earth!" once `ros2 param set` changed its parameter (it sets it back itself)."""
    workspace = new_workspace(tmp_path)
    create(
        workspace,
        "--build-type ament_python --license Apache-2.0 python_parameters --dependencies rclpy",
    )
    package = workspace / "src" / "python_parameters"
    (package / "python_parameters" / "python_parameters_node.py").write_text(
        (DATA / "python_parameters_node.py").read_text()
    )
    add_entry_points(
        package / "setup.py", "minimal_param_node = python_parameters.python_parameters_node:main"
    )
    colcon_build(workspace, "--packages-select python_parameters")
    node = terminal(workspace, "ros2 run python_parameters minimal_param_node")
    try:
        node.wait_for_text("[minimal_param_node]: Hello world!")
        changed = ok(sourced("ros2 param set /minimal_param_node my_parameter earth"), workspace)
        assert changed == "Set parameter successful\n"
        lines = node.wait_for_text("[minimal_param_node]: Hello earth!")
        earth = next(i for i, line in enumerate(lines) if "Hello earth!" in line)
        node.wait_for_output(
            lambda lines: any("Hello world!" in line for line in lines[earth + 1 :]),
            what="Hello world! after Hello earth!",
        )
    finally:
        node.kill()


def test_colcon_test_runs_the_template_linters_and_reports_failed_tests(tmp_path):
    """Testing/CLI and Testing/Python: `colcon test` on a package `ros2 pkg create` made runs
    its three template tests (copyright skipped as the template says, flake8 and pep257 run);
    a failing test is a test failure in `colcon test-result`, not a failed build; a test
    module that cannot be imported is one line saying the tests did not run."""
    workspace = new_workspace(tmp_path)
    create(
        workspace, "--build-type ament_python --license Apache-2.0 --node-name my_node my_package"
    )
    colcon_build(workspace)
    tested = ok(activated("colcon test --ctest-args tests"), workspace, BUILD_TIMEOUT)
    assert "Summary: 1 package finished" in tested and "failed" not in tested
    assert "stderr output" not in tested, tested  # flake8-import-order's pkg_resources warning
    assert ok(activated("colcon test-result --all"), workspace).splitlines() == [
        "build/my_package/pytest.xml: 3 tests, 0 errors, 0 failures, 1 skipped",
        "",
        "Summary: 3 tests, 0 errors, 0 failures, 1 skipped",
    ]
    package = workspace / "src" / "my_package"
    (package / "test" / "test_math.py").write_text("def test_math():\n    assert 2 + 2 == 5\n")
    with (package / "my_package" / "my_node.py").open("a") as node:
        node.write('greeting = "hello"\n')  # flake8-quotes: single quotes preferred
    result = bash(activated("colcon test"), workspace, BUILD_TIMEOUT)
    assert result.returncode == 0, result.stderr
    assert "1 package had test failures: my_package" in result.stdout
    assert "error:" not in result.stderr and "Traceback" not in result.stderr
    shown = bash(activated("colcon test-result --all --verbose"), workspace)
    assert shown.returncode == 1
    assert "build/my_package/pytest.xml: 4 tests, 0 errors, 2 failures, 1 skipped" in shown.stdout
    assert "Q000 Double quotes found but single quotes preferred" in shown.stdout
    assert "assert (2 + 2) == 5" in shown.stdout
    (package / "test" / "test_broken.py").write_text("import no_such_module\n")
    [line] = failure_lines(bash(activated("colcon test"), workspace, BUILD_TIMEOUT))
    assert line.startswith(
        "error: my_package: the tests did not run: src/my_package/test/test_broken.py: "
        "ModuleNotFoundError: No module named 'no_such_module' (full log: log/test_"
    ), line


def test_a_cpp_page_says_rclcpp_needs_a_ros_installation(tmp_path):
    """Writing-A-Simple-Cpp-Publisher-And-Subscriber's package: rclcpp is not on PyPI, and the
    build says so in one line that names the page listing the Python twins."""
    workspace = new_workspace(tmp_path)
    create(
        workspace,
        "--build-type ament_cmake --license Apache-2.0 cpp_pubsub --dependencies rclcpp std_msgs",
    )
    [line] = failure_lines(bash(activated("colcon build"), workspace, BUILD_TIMEOUT))
    cmakelists = (workspace / "src" / "cpp_pubsub" / "CMakeLists.txt").read_text().splitlines()
    number = cmakelists.index("find_package(rclcpp REQUIRED)") + 1
    twins = Path(__file__).resolve().parent.parent / "docs" / "official-tutorials.md"
    assert line.startswith(
        f"error: cpp_pubsub: src/cpp_pubsub/CMakeLists.txt:{number}: find_package(rclcpp): "
        "rclcpp, ROS 2's C++ client library, is not available without a ROS installation "
        f"(it is not on PyPI): the C++ pages cannot build here; their Python twins are listed "
        f"in {twins} (full log: "
    ), line


OVERLAY_NODE = """\
def main():
    print('Hello from the overlay: ros_tutorials_topic in ~/ros2_ws')
"""


def test_a_python_overlay_shadows_the_underlays_package(tmp_path):
    """Creating-A-Workspace's overlay, in Python (docs/official-tutorials.md): a package of
    the workspace named as one of the underlay (this environment's ros_tutorials_topic) wins
    where the workspace is sourced, and the underlay's stays where it is not."""
    workspace = new_workspace(tmp_path)
    create(workspace, "--build-type ament_python --node-name talker ros_tutorials_topic")
    package = workspace / "src" / "ros_tutorials_topic"
    (package / "ros_tutorials_topic" / "talker.py").write_text(OVERLAY_NODE)
    colcon_build(workspace)
    overlay = "source install/local_setup.bash\n"
    shown = ok(activated(overlay + "ros2 run ros_tutorials_topic talker"), workspace)
    assert shown == "Hello from the overlay: ros_tutorials_topic in ~/ros2_ws\n"
    prefix = ok(activated(overlay + "ros2 pkg prefix ros_tutorials_topic"), workspace)
    assert prefix == f"{workspace / 'install' / 'ros_tutorials_topic'}\n"
    assert ok(activated("ros2 pkg prefix ros_tutorials_topic"), workspace) == f"{sys.prefix}\n"


def test_colcon_cd_with_this_environments_lines(tmp_path):
    """Colcon-Tutorial's "Setup colcon_cd", with the lines docs/official-tutorials.md gives:
    colcon_cd PKG goes to the package's folder in the workspace; colcon's tab completion
    hook is there too."""
    workspace = new_workspace(tmp_path)
    create(workspace, "--build-type ament_python my_package")
    share = Path(sys.prefix) / "share"
    script = (
        f"source {share}/colcon_cd/function/colcon_cd.sh\n"
        f"export _colcon_cd_root={workspace}\n"
        "colcon_cd my_package && pwd"
    )
    shown = ok(activated(script), tmp_path)
    assert shown.splitlines()[-1] == str(workspace / "src" / "my_package")
    assert (share / "colcon_argcomplete" / "hook" / "colcon-argcomplete.bash").is_file()


def test_a_package_named_as_a_seeds_built_but_not_sourced_is_not_the_lesson(tmp_path):
    """`my_package` (seed 004's name) and `pub_sub` (seed 003's), the learner's own, built in
    ~/ros2_ws and not sourced: the same line as any other name, not the lesson's node."""
    workspace = new_workspace(tmp_path)
    create(workspace, "--build-type ament_python --node-name talker my_package")
    create(workspace, "--build-type ament_python --node-name publisher pub_sub")
    colcon_build(workspace)
    for command in (
        "ros2 run my_package talker",
        "rosrun my_package talker",
        "ros2 run pub_sub publisher",
        "ros2 launch my_package talker.launch",
    ):
        result = bash(activated(command), workspace)
        assert result.returncode == 1 and result.stdout == "", (command, result.stdout)
        assert result.stderr.count("\n") == 1, result.stderr
        assert "is built in" in result.stderr and "but that workspace is not sourced" in (
            result.stderr
        ), (command, result.stderr)
    # Sourced, the learner's own package runs.
    shown = ok(sourced("ros2 run my_package talker"), workspace)
    assert shown == "Hi from my_package.\n"


def in_terminal(script: str, cwd: Path, timeout: float) -> tuple[int, str]:
    """Run SCRIPT in bash with a pseudo-terminal as its terminal (stdin, stdout, stderr), as a
    learner types it; its exit status and everything it wrote."""
    import pty
    import select

    main, side = pty.openpty()
    process = subprocess.Popen(
        ["bash", "-c", script],
        cwd=cwd,
        env={**learner_environment(), "TERM": "xterm-256color"},
        stdin=side,
        stdout=side,
        stderr=side,
        start_new_session=True,
    )
    os.close(side)
    output = bytearray()
    try:
        while True:
            ready, _, _ = select.select([main], [], [], timeout)
            if not ready:
                process.kill()
                pytest.fail(f"{script!r} wrote nothing for {timeout:.0f} s: {bytes(output)!r}")
            try:
                chunk = os.read(main, 65536)
            except OSError:  # the terminal closed: every process on it ended
                break
            if not chunk:
                break
            output += chunk
        return process.wait(timeout=timeout), output.decode(errors="replace")
    finally:
        os.close(main)
        if process.poll() is None:
            process.kill()


def test_a_cpp_page_in_a_terminal_says_why_too(tmp_path):
    """Typed in a terminal, colcon has CMake colour its errors: the one line still explains
    (rclcpp needs a ROS installation, the Python twins' page), without colour codes in it."""
    workspace = new_workspace(tmp_path)
    create(workspace, "--build-type ament_cmake cpp_pubsub --dependencies rclcpp std_msgs")
    status, output = in_terminal(
        activated("colcon build --packages-select cpp_pubsub"), workspace, BUILD_TIMEOUT
    )
    assert status != 0, output
    lines = [line for line in output.splitlines() if line.startswith("error: cpp_pubsub")]
    assert len(lines) == 1, output
    why = "find_package(rclcpp): rclcpp, ROS 2's C++ client library, is not available"
    assert why in lines[0], output
    assert "\x1b" not in lines[0], lines[0]


def test_a_cpp_package_beside_python_ones_is_left_out_and_the_rest_builds(tmp_path):
    """Creating-A-Workspace's turtlesim clone (C++, rclcpp) in src/ beside the docs' Python
    overlay: colcon builds the Python package and says in one line why turtlesim is left out;
    named, it is tried and fails with colcon's one line."""
    workspace = new_workspace(tmp_path)
    (workspace / "src" / "ros_tutorials").mkdir()
    ok(
        activated("ros2 pkg create --build-type ament_cmake turtlesim --dependencies rclcpp"),
        workspace / "src" / "ros_tutorials",
    )
    create(workspace, "--build-type ament_python --node-name talker ros_tutorials_topic")
    result = bash(activated("colcon build"), workspace, BUILD_TIMEOUT)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "Summary: 1 package finished" in result.stdout, result.stdout
    notes = [line for line in result.stderr.splitlines() if line.startswith("note: ")]
    assert len(notes) == 1 and notes[0].startswith(
        "note: turtlesim is left out: rclcpp, ROS 2's C++ client library, is not available"
    ), result.stderr
    assert notes[0].endswith("(`colcon build --packages-select turtlesim` tries it)")
    listed = ok(activated("colcon list --names-only"), workspace).split()
    assert sorted(listed) == ["ros_tutorials_topic", "turtlesim"]
    [line] = failure_lines(
        bash(activated("colcon build --packages-select turtlesim"), workspace, BUILD_TIMEOUT)
    )
    assert "find_package(rclcpp)" in line
