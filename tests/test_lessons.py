"""The lesson files as a course: each is plain rclpy (the standard library, rclpy and interface
packages; no code of this project) and carries none of the toolkit's hardening; only the lesson
that teaches changing a log level at run time serves the logger-level services; and the docs'
table of lengths (docs/lesson-files.md) is the files' own and keeps its target. tests/
test_lessons_in_own_package.py runs them in a package of one's own."""

from __future__ import annotations

import ast
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import spin_until

from ros_tutorials_common import lesson_scripts, packages
from ros_tutorials_topic.publisher import TopicPublisher

ROOT = Path(__file__).resolve().parent.parent
LESSONS = ("ros_tutorials_topic", "ros_tutorials_service", "ros_tutorials_parameter",
           "ros_tutorials_action")  # fmt: skip
DEMOS = ("ros_tutorials_demo_nodes",)  # ros2/demos' nodes: plain rclpy too


def modules(*packages: str) -> list[Path]:
    return sorted(
        path for package in packages for path in (ROOT / package).glob("*.py")
        if path.name != "__init__.py"
    )  # fmt: skip


LESSON_FILES = modules(*LESSONS)


def lesson_name(path: Path) -> str:
    return f"{path.parent.name}/{path.name}"


def imports(path: Path) -> list[tuple[int, str]]:
    """(level, module) of each import: level 0 absolute, 1 from the file's own package."""
    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            found.append((node.level, node.module or ""))
        elif isinstance(node, ast.Import):
            found += [(0, alias.name) for alias in node.names]
    return found


def plain_rclpy(level: int, module: str, path: Path) -> bool:
    """The standard library, rclpy, an interface package (X.msg, X.srv, X.action), or a file
    beside this one (copied with it)."""
    if level:
        return level == 1 and (path.parent / f"{module}.py").is_file()
    top = module.split(".")[0]
    return (
        top in sys.stdlib_module_names
        or top == "rclpy"
        or bool(re.fullmatch(r"\w+\.(msg|srv|action)", module))
    )


@pytest.mark.parametrize("path", modules(*LESSONS, *DEMOS), ids=lesson_name)
def test_a_lesson_is_plain_rclpy(path):
    others = [module for level, module in imports(path) if not plain_rclpy(level, module, path)]
    assert not others, f"{lesson_name(path)} imports {others}"


@pytest.mark.parametrize("path", modules(*LESSONS, *DEMOS), ids=lesson_name)
def test_a_lesson_shows_init_spin_and_shutdown(path):
    source = path.read_text()
    assert "rclpy.init(args=args" in source and "rclpy.try_shutdown()" in source
    assert "ros_tutorials_common" not in source and "DISCOVERY" not in source


# The lessons whose log level is changed while they run (docs/rqt-and-logging.md:
# rqt_logger_level /ns1/topic_publisher warn; seed 004's step 30 on its talker): the nodes
# that serve the logger services.
LOGGING_LESSONS = (
    ROOT / "ros_tutorials_topic" / "publisher.py",
    ROOT / "ros_tutorials_topic" / "workshop_talker.py",
)


def node_creations(path: Path) -> list[ast.Call]:
    return [
        call for call in ast.walk(ast.parse(path.read_text()))
        if isinstance(call, ast.Call) and ast.unparse(call.func) in ("Node", "super().__init__")
    ]  # fmt: skip


@pytest.mark.parametrize("path", LESSON_FILES, ids=lesson_name)
def test_only_the_logging_lessons_serve_logger_levels(path):
    nodes = node_creations(path)
    assert nodes, f"{path.name} creates no node"
    for call in nodes:
        flags = {kw.arg: ast.unparse(kw.value) for kw in call.keywords}
        expected = "True" if path in LOGGING_LESSONS else None
        assert flags.get("enable_logger_service") == expected, ast.unparse(call)


def test_the_logging_lesson_serves_the_logger_level_services(context, executor):
    node = TopicPublisher(context=context)
    executor.add_node(node)
    name = node.get_fully_qualified_name()
    spin_until(
        executor,
        lambda: (
            {f"{name}/get_logger_levels", f"{name}/set_logger_levels"}
            <= {service for service, _ in node.get_service_names_and_types()}
        ),
        what=f"{name}'s logger-level services",
    )


@pytest.mark.parametrize("path", LESSON_FILES, ids=lesson_name)
def test_a_lesson_carries_no_hardening(path):
    """Numbers are argparse's int and float, goal states GoalStatus names, and rclpy's shutdown
    race is handled where the lessons start (ros_tutorials_common/lesson_scripts.py)."""
    tree = ast.parse(path.read_text())
    for call in ast.walk(tree):
        if isinstance(call, ast.Call) and ast.unparse(call.func).endswith(".add_argument"):
            kinds = {ast.unparse(kw.value) for kw in call.keywords if kw.arg == "type"}
            assert kinds <= {"int", "float"}, ast.unparse(call)
    assert "rclpy.ok()" not in ast.unparse(tree), "rclpy's shutdown race is handled elsewhere"
    assert "signal_handler_options" not in ast.unparse(tree), "Ctrl-C is rclpy's, as upstream"
    assert not {"nan", "inf", "1e6"} & set(re.findall(r"[\w.]+", path.read_text()))
    assert not re.search(r"^import re$", path.read_text(), re.M), "numbers are argparse's int"
    if "ActionClient(" in path.read_text():
        assert "GoalStatus.STATUS_SUCCEEDED" in path.read_text()


# docs/lesson-files.md's table: | `file` | lines | book's original | lines | official | lines |
# ratio |; a ratio is the lines over the longer of the two originals.
ROW = re.compile(
    r"^\| `(ros_tutorials_\w+/\w+\.py)` \| (\d+) \| [^|]+ \| (\d+|-) \| [^|]+ \| (\d+) \| "
    r"(\d\.\d\d) \|$",
    re.M,
)
TARGET = 1.3  # no lesson over 1.3 times the longer of the book's file and the official one


def test_the_docs_list_each_lesson_files_length_and_keep_the_target():
    table = (ROOT / "docs" / "lesson-files.md").read_text()
    assert f"no file over {TARGET} times" in table
    rows = {path: (int(n), book, int(official), ratio) for path, n, book, official, ratio in
            ROW.findall(table)}  # fmt: skip
    actual = {
        str(path.relative_to(ROOT)): len(path.read_text().splitlines()) for path in LESSON_FILES
    }
    assert {path: row[0] for path, row in rows.items()} == actual
    for path, (lines, book, official, ratio) in rows.items():
        longer = max(official, 0 if book == "-" else int(book))
        assert ratio == f"{lines / longer:.2f}", path
        assert lines <= TARGET * longer, f"{path}: {lines} lines, over {TARGET} x {longer}"


def test_the_console_scripts_take_rclpys_shutdown_race_for_the_stop(monkeypatch, tmp_path):
    """The race the lessons no longer carry: a timer's publish after rclpy's Ctrl-C handler
    shut ROS down is the stop (status 0) where the console scripts start the lessons; any other
    RuntimeError stays an error."""
    (tmp_path / "racing_lesson.py").write_text("def main():\n    raise RuntimeError(MESSAGE)\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    import racing_lesson

    monkeypatch.setattr(
        racing_lesson, "MESSAGE", "Failed to publish: publisher's context is invalid", raising=False
    )
    assert lesson_scripts.run("racing_lesson") == 0
    monkeypatch.setattr(racing_lesson, "MESSAGE", "another error")
    with pytest.raises(RuntimeError, match="another error"):
        lesson_scripts.run("racing_lesson")


@pytest.mark.parametrize(
    ("raised", "status"),
    [
        ('RuntimeError("failed to initialize wait set: the given context is not valid")', 0),
        ('RuntimeError("Failed to publish: publisher\'s context is invalid")', 0),
        ('RuntimeError("another error")', 1),
    ],
)
def test_a_lesson_started_by_ros2_run_takes_the_race_for_the_stop(tmp_path, raised, status):
    """`ros2 run` and the launcher start a lesson as `python -m
    ros_tutorials_common.lesson_scripts PKG.MODULE` (packages.py): rclpy's shutdown race is the
    stop there (status 0, nothing printed), and a Ctrl-C that Python lost in a __del__ is not
    printed either; any other error stays one. The lesson's package imports nothing of it."""
    package = tmp_path / "racing"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "lesson.py").write_text(
        "import sys\n"
        "assert sys.argv[1:] == ['--ros-args'], sys.argv\n"
        "class Late:\n"
        "    def __del__(self):\n"
        "        raise KeyboardInterrupt\n"
        "Late()\n"
        f"raise {raised}\n"
    )
    env = {**os.environ, "PYTHONPATH": f"{tmp_path}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
    result = subprocess.run(
        [*lesson_scripts.command("racing.lesson"), "--ros-args"],
        capture_output=True, text=True, env=env, timeout=60,
    )  # fmt: skip
    assert result.returncode == status, result.stderr
    if status == 0:
        assert result.stdout == result.stderr == ""
    else:
        assert "another error" in result.stderr


def test_a_ctrl_c_in_rclpys_message_conversion_is_the_stop_of_a_lesson(tmp_path):
    """A Ctrl-C that lands while rclpy's C++ converts a message comes out of pybind11 as its
    own RuntimeError; where the lesson started, after a press, that is the stop (status 0)."""
    (tmp_path / "converting.py").write_text(
        "import os, signal\n"
        "try:\n"
        "    os.kill(os.getpid(), signal.SIGINT)\n"
        "    sum(range(10))  # the KeyboardInterrupt comes here\n"
        "except KeyboardInterrupt:\n"
        "    pass\n"
        "raise RuntimeError(\"Unable to convert call argument '0' to Python object\")\n"
    )
    env = {**os.environ, "PYTHONPATH": f"{tmp_path}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
    result = subprocess.run(
        lesson_scripts.command("converting"), capture_output=True, text=True, env=env, timeout=60
    )
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""


def test_lessons_packages_run_through_the_lesson_start():
    """`ros2 run` and the launcher start a lesson where the project handles rclpy's shutdown
    race (lesson_scripts), not through the lesson's package."""
    line = packages.command("ros_tutorials_topic", "talker")
    assert line[:3] == [sys.executable, "-m", "ros_tutorials_common.lesson_scripts"]
    assert packages.module_of(line) == "ros_tutorials_topic.talker"
    assert packages.module_of(packages.command("tf2_ros", "tf2_echo")) == "tf2_ros.tf2_echo"


@pytest.mark.parametrize("ros", ["up", "shut down"])
def test_rclpys_reports_of_a_thread_after_the_stop_are_not_printed_where_a_lesson_starts(
    tmp_path, ros
):
    """An action server's goal thread carries on after rclpy's signal handler shut ROS down,
    and rclpy reports its calls on the shut-down context: where the lesson starts, those
    reports (and the traceback after one) are dropped once ROS is down, and only then."""
    reports = (
        "[ERROR] [1.5] [server.action_server]: Error raised in execute callback: failed\n"
        "Failed to publish log message to rosout: publisher's context is invalid, at x.c:1\n"
        "Traceback (most recent call last):\n"
        '  File "server.py", line 1, in execute\n'
        "RCLError: Failed get goal status array: feedback publisher is invalid\n"
        "[WARN] [1.5] [server.action_server]: Failed to send result response (the client "
        "may have gone away)\n"
    )
    (tmp_path / "goal_thread.py").write_text(
        "import os, sys, rclpy\n"
        "rclpy.init()\n"
        f"{'rclpy.shutdown()' if ros == 'shut down' else ''}\n"
        f"os.write(2, {reports!r}.encode())\n"
        "print('the lesson goes on', file=sys.stderr)\n"
    )
    env = {**os.environ, "PYTHONPATH": f"{tmp_path}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
    result = subprocess.run(
        lesson_scripts.command("goal_thread"), capture_output=True, text=True, env=env, timeout=60
    )
    assert result.returncode == 0, result.stderr
    assert result.stderr == (reports if ros == "up" else "") + "the lesson goes on\n"
