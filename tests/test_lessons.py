"""The lesson files as a course: each stands alone, every node serves the logger-level
services, and the docs' table of lengths (docs/lesson-files.md) is the files' own."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest
from helpers import spin_until

from ros_tutorials_action.server import FibonacciActionServer
from ros_tutorials_parameter.server import ServiceServerWithParameter
from ros_tutorials_topic.publisher import TopicPublisher

ROOT = Path(__file__).resolve().parent.parent
LESSONS = ("ros_tutorials_topic", "ros_tutorials_service", "ros_tutorials_parameter",
           "ros_tutorials_action")  # fmt: skip
LESSON_FILES = sorted(
    path for package in LESSONS for path in (ROOT / package).glob("*.py")
    if path.name != "__init__.py"
)  # fmt: skip

# Lesson files that are another lesson's program under the lesson's own name, as in the book
# (the parameter lesson changes only the server; its client is the service lesson's client).
REUSED = {"ros_tutorials_parameter/client.py": "ros_tutorials_service.client"}


def lesson_name(path: Path) -> str:
    return f"{path.parent.name}/{path.name}"


def imported_modules(path: Path) -> set[str]:
    modules = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module:
            modules.add(node.module)
        elif isinstance(node, ast.Import):
            modules.update(alias.name for alias in node.names)
    return modules


@pytest.mark.parametrize("path", LESSON_FILES, ids=lesson_name)
def test_a_lesson_imports_no_other_lesson(path):
    others = {m for m in imported_modules(path) if m.split(".")[0] in LESSONS}
    reused = REUSED.get(lesson_name(path))
    if reused:  # `from ros_tutorials_service import client`
        others = {m for m in others if m != reused.rpartition(".")[0]}
    assert not others, f"{path.name} imports {others}"


@pytest.mark.parametrize("name", sorted(REUSED))
def test_a_reused_lesson_runs_the_others_main_and_nothing_else(name):
    tree = ast.parse((ROOT / name).read_text())
    package, _, module = REUSED[name].rpartition(".")
    imports = [ast.unparse(node) for node in tree.body if isinstance(node, ast.ImportFrom)]
    assert imports == [f"from {package} import {module}"]
    (main,) = [node for node in tree.body if isinstance(node, ast.FunctionDef)]
    assert f"return {module}.main(args, " in ast.unparse(main)
    assert "rclpy" not in (ROOT / name).read_text()


@pytest.mark.parametrize(
    "path", [p for p in LESSON_FILES if lesson_name(p) not in REUSED], ids=lesson_name
)
def test_a_lesson_shows_init_and_shutdown_and_serves_logger_levels(path):
    source = path.read_text()
    assert "rclpy.init(" in source and "rclpy.try_shutdown()" in source
    nodes = [
        call for call in ast.walk(ast.parse(source))
        if isinstance(call, ast.Call) and ast.unparse(call.func) in ("Node", "super().__init__")
    ]  # fmt: skip
    assert nodes, f"{path.name} creates no node"
    for call in nodes:
        flags = {kw.arg: ast.unparse(kw.value) for kw in call.keywords}
        assert flags.get("enable_logger_service") == "True", ast.unparse(call)


@pytest.mark.parametrize(
    "make", [TopicPublisher, ServiceServerWithParameter, FibonacciActionServer]
)
def test_nodes_serve_the_logger_level_services(context, executor, make):
    node = make(context=context)
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


def test_the_docs_list_each_lesson_files_length():
    table = (ROOT / "docs" / "lesson-files.md").read_text()
    listed = dict(re.findall(r"^\| `(ros_tutorials_\w+/\w+\.py)` \| (\d+) \|", table, re.M))
    actual = {
        str(path.relative_to(ROOT)): str(len(path.read_text().splitlines()))
        for path in LESSON_FILES
    }
    assert listed == actual
