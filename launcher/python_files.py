"""Python launch files (``*_launch.py``, ``*.launch.py``): not run by this launcher yet.

`ros2 launch demo_nodes_cpp introspect_services_launch.py` gets one line instead, naming the
`ros2 run` commands that start the same nodes, read from the file's ``Node(package=...,
executable=...)`` calls (without running it).
"""

from __future__ import annotations

import ast
from pathlib import Path


def is_python_launch_file(path: Path) -> bool:
    return path.name.endswith(".py")


def run_commands(path: Path) -> list[str]:
    """`ros2 run PKG EXE` for each Node(...) the file creates with literal names, in order."""
    try:
        tree = ast.parse(path.read_text(encoding="utf-8"))
    except (OSError, SyntaxError, UnicodeDecodeError, ValueError):
        return []
    commands = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        called = node.func.attr if isinstance(node.func, ast.Attribute) else None
        called = node.func.id if isinstance(node.func, ast.Name) else called
        if called != "Node":
            continue
        words = {
            keyword.arg: keyword.value.value
            for keyword in node.keywords
            if isinstance(keyword.value, ast.Constant) and isinstance(keyword.value.value, str)
        }
        if "package" in words and "executable" in words:
            commands.append(f"ros2 run {words['package']} {words['executable']}")
    return sorted(set(commands), key=commands.index)


def not_supported(path: Path) -> str:
    """The one line that says what to type instead of launching a Python launch file."""
    message = f"{path.name} is a Python launch file, which this launcher cannot run yet"
    commands = [f"`{command}`" for command in run_commands(path)]
    if not commands:
        return message + "; start its nodes with `ros2 run PKG EXECUTABLE`"
    listed = (
        commands[0] if len(commands) == 1 else ", ".join(commands[:-1]) + " and " + commands[-1]
    )
    return f"{message}; start its nodes instead, each in a terminal of its own: {listed}"
