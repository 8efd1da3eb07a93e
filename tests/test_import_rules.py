"""What the course and tf2 may import: a lesson package (its ``__init__.py`` too) imports only
the standard library, rclpy and interface packages, so that a learner's copy runs as the
original; tf2's packages import nothing of the command line (``ros2cmd``) or of where the
lessons start (``lesson_scripts``): they stand on the toolkit's floor, ros_tutorials_common."""

from __future__ import annotations

import ast
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
LESSON_PACKAGES = [
    "ros_tutorials_topic",
    "ros_tutorials_service",
    "ros_tutorials_parameter",
    "ros_tutorials_action",
]
TF2_PACKAGES = ["tf2_py", "tf2_ros", "tf2_geometry_msgs", "tf2_tools"]
INTERFACE_KINDS = {"msg", "srv", "action"}


def imported_modules(source: Path) -> list[tuple[str, int]]:
    """(module, line) of every import statement of a file, wherever it stands."""
    found = []
    for node in ast.walk(ast.parse(source.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found += [(alias.name, node.lineno) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            found.append(("." * node.level + (node.module or ""), node.lineno))
    return found


def allowed_in_a_lesson(module: str) -> bool:
    top, _, rest = module.partition(".")
    if top in sys.stdlib_module_names or top == "rclpy":
        return True
    # `from std_msgs.msg import String`: an interface package's generated module.
    return rest.split(".")[0] in INTERFACE_KINDS and not (ROOT / top).is_dir()


@pytest.mark.parametrize("package", LESSON_PACKAGES)
def test_a_lesson_package_imports_only_rclpy_the_standard_library_and_interfaces(package):
    files = sorted((ROOT / package).glob("*.py"))
    assert ROOT / package / "__init__.py" in files
    wrong = [
        f"{source.relative_to(ROOT)}:{line}: {module}"
        for source in files
        for module, line in imported_modules(source)
        if not allowed_in_a_lesson(module)
    ]
    assert not wrong, "\n".join(wrong)


def test_the_rule_refuses_the_projects_own_modules():
    assert not allowed_in_a_lesson("ros_tutorials_common.lesson_scripts")
    assert not allowed_in_a_lesson("ros2cmd.errors")
    assert not allowed_in_a_lesson(".talker")
    assert allowed_in_a_lesson("ros_tutorials_interfaces.srv")
    assert allowed_in_a_lesson("rclpy.executors")


@pytest.mark.parametrize("package", TF2_PACKAGES)
def test_tf2_imports_nothing_of_the_command_line_or_the_lessons_start(package):
    wrong = [
        f"{source.relative_to(ROOT)}:{line}: {module}"
        for source in sorted((ROOT / package).rglob("*.py"))
        for module, line in imported_modules(source)
        if module.split(".")[0] == "ros2cmd" or module.endswith("lesson_scripts")
    ]
    assert not wrong, "\n".join(wrong)
