"""The lesson files as a course: each is plain rclpy (the standard library, rclpy and interface
packages; no code of this project), every node serves the logger-level services, and the docs'
table of lengths (docs/lesson-files.md) is the files' own. tests/test_take_home.py runs them in a
package of one's own."""

from __future__ import annotations

import ast
import re
import sys
from pathlib import Path

import pytest
from helpers import spin_until

from ros_tutorials_action.server import FibonacciActionServer
from ros_tutorials_parameter.server import ServiceServerWithParameter
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


@pytest.mark.parametrize("path", LESSON_FILES, ids=lesson_name)
def test_a_lesson_node_serves_logger_levels(path):
    nodes = [
        call for call in ast.walk(ast.parse(path.read_text()))
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
