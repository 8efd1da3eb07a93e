"""What may import what in this project, read from the source (the import graph):
- no import cycles among the project's modules;
- the launch stack imports only down (``LAUNCH_LAYERS``), has no circle of packages and names
  no floor above it;
- the libraries stand below the command line (rosbag2 below rosbag2_py below ``ros2 bag``; tf2's
  packages import nothing of ``ros2cmd`` or of where the lessons start, ``lesson_scripts``);
- a lesson package (its ``__init__.py`` too) imports only the standard library, rclpy and
  interface packages, so that a learner's copy runs as the original.

Every module of the project's packages (each top-level folder with an ``__init__.py``) is a
node; every import statement that names another of them is an edge, wherever it is written: at
the top of a module or inside a function (a function's import runs too, only later, and a
cycle through it is a cycle of the design). Two kinds of import are not edges:
- one under ``if TYPE_CHECKING:``, which never runs: it names a type for the reader and the
  type checker, as ros2/launch writes its own;
- the implicit import of a module's parent packages (``import launch.actions`` runs
  launch/__init__.py first): a package's ``__init__`` that gathers its modules (launch/, as
  ros2/launch's does) would otherwise make a cycle with each of them. ``from launch import
  LaunchDescription`` names the package itself and is an edge to it.
The lesson and tf2 rules read every import statement of a file, also one for types only.
"""

from __future__ import annotations

import ast
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
NOT_PACKAGES = {"build", "tests", "benchmarks", "tools", "interfaces", "docs"}


@dataclass(frozen=True)
class Edge:
    target: str
    where: str  # path:line of the import statement


def project_modules(root: Path) -> dict[str, Path]:
    """Module name -> source file, for every module of root's top-level packages."""
    modules = {}
    for init in sorted(root.glob("*/__init__.py")):
        package = init.parent
        if package.name.startswith(".") or package.name in NOT_PACKAGES:
            continue
        for source in sorted(package.rglob("*.py")):
            parts = list(source.relative_to(root).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts.pop()
            modules[".".join(parts)] = source
    return modules


def _type_checking_only(node: ast.If) -> bool:
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _imports(tree: ast.AST, type_only: bool = False) -> Iterator[ast.Import | ast.ImportFrom]:
    """Every import statement that can run: module level, in functions and classes, in
    branches and try blocks; not under ``if TYPE_CHECKING:`` (its else branch does run),
    unless ``type_only`` (then those too: a type named from a floor above is still a
    dependency on it)."""
    for child in ast.iter_child_nodes(tree):
        if isinstance(child, (ast.Import, ast.ImportFrom)):
            yield child
        elif isinstance(child, ast.If) and _type_checking_only(child) and not type_only:
            for branch in child.orelse:
                yield from _imports(ast.Module(body=[branch], type_ignores=[]))
        else:
            yield from _imports(child, type_only)


def edges_of(
    name: str, source: Path, modules: dict[str, Path], root: Path, type_only: bool = False
) -> list[Edge]:
    """The modules of the project that the module ``name`` imports, with file:line (with
    ``type_only``, those imported under ``if TYPE_CHECKING:`` too)."""
    tree = ast.parse(source.read_text(encoding="utf-8"), filename=str(source))
    package = name.split(".") if source.name == "__init__.py" else name.split(".")[:-1]
    shown = source.relative_to(root)
    found = []
    for statement in _imports(tree, type_only):
        where = f"{shown}:{statement.lineno}"
        if isinstance(statement, ast.Import):
            for alias in statement.names:
                parts = alias.name.split(".")
                # `import a.b.c` is an edge to the deepest of a.b.c, a.b, a that is ours.
                for end in range(len(parts), 0, -1):
                    if ".".join(parts[:end]) in modules:
                        found.append(Edge(".".join(parts[:end]), where))
                        break
            continue
        if statement.level:  # from . import x, from ..a import b
            base = package[: len(package) - statement.level + 1]
            origin = ".".join([*base, *([statement.module] if statement.module else [])])
        else:
            origin = statement.module or ""
        for alias in statement.names:
            submodule = f"{origin}.{alias.name}"
            if submodule in modules:  # `from launcher import guardian`: the module
                found.append(Edge(submodule, where))
            elif origin in modules:  # `from launcher import LaunchError`: the package
                found.append(Edge(origin, where))
    return [edge for edge in found if edge.target != name]


def import_graph(root: Path, type_only: bool = False) -> dict[str, list[Edge]]:
    modules = project_modules(root)
    return {
        name: edges_of(name, source, modules, root, type_only) for name, source in modules.items()
    }


def strongly_connected(graph: dict[str, list[Edge]]) -> list[list[str]]:
    """The groups of modules that reach each other (Tarjan's algorithm, without recursion)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    groups = []
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(graph[start]))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, targets = work[-1]
            for edge in targets:
                if edge.target not in index:
                    index[edge.target] = low[edge.target] = len(index)
                    stack.append(edge.target)
                    on_stack.add(edge.target)
                    work.append((edge.target, iter(graph[edge.target])))
                    break
                if edge.target in on_stack:
                    low[node] = min(low[node], index[edge.target])
            else:
                work.pop()
                if work:
                    parent = work[-1][0]
                    low[parent] = min(low[parent], low[node])
                if low[node] == index[node]:
                    group = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        group.append(member)
                        if member == node:
                            break
                    if len(group) > 1:
                        groups.append(sorted(group))
    return groups


def one_cycle(graph: dict[str, list[Edge]], group: list[str]) -> str:
    """A shortest cycle through the group's first module, as 'a (a.py:3) -> b (b.py:9) -> a'."""
    start = group[0]
    members = set(group)
    came_from: dict[str, tuple[str, Edge]] = {}
    frontier = [start]
    while frontier:
        following = []
        for node in frontier:
            for edge in graph[node]:
                if edge.target not in members or edge.target in came_from:
                    continue
                came_from[edge.target] = (node, edge)
                following.append(edge.target)
        if start in came_from:
            break
        frontier = following
    steps = []
    node = start
    while True:
        node, edge = came_from[node]
        steps.append(f"{node} ({edge.where}) -> ")
        if node == start:
            break
    return "".join(reversed(steps)) + start


def cycles(root: Path) -> list[str]:
    graph = import_graph(root)
    return [one_cycle(graph, group) for group in strongly_connected(graph)]


def test_the_project_has_no_import_cycle():
    graph = import_graph(ROOT)
    found = [
        f"{', '.join(group)} import each other, e.g.\n  {one_cycle(graph, group)}"
        for group in strongly_connected(graph)
    ]
    assert not found, "import cycles (move the shared piece down):\n" + "\n".join(found)


def test_the_graph_is_the_projects():
    graph = import_graph(ROOT)
    assert {"ros2cmd.cli", "launcher.loading", "ros_tutorials_common.packages"} <= graph.keys()
    targets = {edge.target for edge in graph["ros2cmd.run"]}
    assert "ros_tutorials_common.packages" in targets  # from ros_tutorials_common import ...
    assert "ros2cmd.errors" in targets


def _write(root: Path, files: dict[str, str]) -> None:
    for name, text in files.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text)


def test_a_cycle_through_a_function_level_import_is_found_and_named(tmp_path):
    _write(
        tmp_path,
        {
            "pkg/__init__.py": "",
            "pkg/a.py": "from pkg.b import run\n",
            "pkg/b.py": "def run():\n    from . import a\n",
            "pkg/c.py": "import pkg.a\n",  # reaches the cycle, is not in it
        },
    )
    assert cycles(tmp_path) == ["pkg.a (pkg/a.py:1) -> pkg.b (pkg/b.py:2) -> pkg.a"]


def test_type_checking_imports_and_parent_packages_are_not_edges(tmp_path):
    _write(
        tmp_path,
        {
            "pkg/__init__.py": "from pkg.a import A\n",
            "pkg/a.py": "from typing import TYPE_CHECKING\n"
            "if TYPE_CHECKING:\n    from pkg.b import B\nelse:\n    import pkg.c\nA = 1\n",
            "pkg/b.py": "from pkg.a import A\nB = A\n",
            "pkg/c.py": "",
        },
    )
    graph = import_graph(tmp_path)
    assert [edge.target for edge in graph["pkg.a"]] == ["pkg.c"]  # the else branch runs
    assert [edge.target for edge in graph["pkg.b"]] == ["pkg.a"]
    assert cycles(tmp_path) == []
    # A name of the package itself (not one of its modules) is an edge to its __init__.
    _write(tmp_path, {"pkg/a.py": "from pkg import B\n"})
    assert cycles(tmp_path) == ["pkg (pkg/__init__.py:1) -> pkg.a (pkg/a.py:1) -> pkg"]


def test_the_launch_model_knows_the_launcher_only_through_its_interface():
    # launch/ and launch_ros/ (the model: entities, substitutions, the executor's context)
    # hand their results to launch_foundation.declarations.PlanSink; they import neither the
    # resolver nor the front-ends' parser of tags, and read no resolver attribute.
    graph = import_graph(ROOT)
    model = [name for name in graph if name.split(".")[0] in ("launch", "launch_ros")]
    assert "launch_ros.actions" in model and "launch._base" in model
    reaching = [
        f"{name} -> {edge.target} ({edge.where})"
        for name in model
        for edge in graph[name]
        if edge.target.split(".")[0] == "launcher"
    ]
    assert not reaching, "the launch model imports the launcher's resolver:\n" + "\n".join(reaching)
    pokes = [
        f"{path.relative_to(ROOT)}:{number}"
        for package in ("launch", "launch_ros")
        for path in sorted((ROOT / package).rglob("*.py"))
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
        if ".resolver" in line or "context.scope" in line
    ]
    assert not pokes, "the launch model reads the resolver's internals:\n" + "\n".join(pokes)


# The launch stack's floors, bottom to top, and what each package may import (besides itself
# and the standard library): docs/dev/architecture.md draws them. A package not named here is
# no part of the stack and may not be imported by it.
LAUNCH_LAYERS: dict[str, set[str]] = {
    "ros_tutorials_common": set(),  # the project's floor: nothing of the launch stack
    "launch_foundation": {"ros_tutorials_common"},
    "launch": {"launch_foundation", "ros_tutorials_common"},
    "launch_xml": {"launch", "launch_foundation", "ros_tutorials_common"},
    "launch_yaml": {"launch", "launch_xml", "launch_foundation", "ros_tutorials_common"},
    "launch_ros": {"launch", "launch_foundation", "ros_tutorials_common"},
    "launcher": {
        "launch",
        "launch_ros",
        "launch_xml",
        "launch_yaml",
        "launch_foundation",
        "ros_tutorials_common",
    },
}
LAUNCH_STACK = set(LAUNCH_LAYERS) - {"ros_tutorials_common"}


def layer_breaches(root: Path, layers: dict[str, set[str]], stack: set[str]) -> list[str]:
    """Each import, type-only ones included, from a package of ``layers`` to a package of
    ``stack`` it may not import, as 'a.b (a/b.py:3) -> c.d'."""
    graph = import_graph(root, type_only=True)
    breaches = []
    for name, edges in sorted(graph.items()):
        package = name.split(".")[0]
        if package not in layers:
            continue
        for edge in edges:
            target = edge.target.split(".")[0]
            if target != package and target in (stack | set(layers)) - layers[package]:
                breaches.append(f"{name} ({edge.where}) -> {edge.target}")
    return breaches


def test_the_launch_stack_imports_only_down():
    breaches = layer_breaches(ROOT, LAUNCH_LAYERS, LAUNCH_STACK)
    assert not breaches, (
        "imports that run up (or across) the launch stack's floors "
        "(docs/dev/architecture.md; move the shared piece down):\n" + "\n".join(breaches)
    )


def test_the_launch_stack_has_no_circle_of_packages():
    # A circle of packages is a circle even where no two modules import each other.
    graph = import_graph(ROOT, type_only=True)
    packages: dict[str, list[Edge]] = {package: [] for package in LAUNCH_LAYERS}
    for name, edges in graph.items():
        if name.split(".")[0] in packages:
            packages[name.split(".")[0]] += [
                Edge(edge.target.split(".")[0], edge.where)
                for edge in edges
                if edge.target.split(".")[0] in packages
                and edge.target.split(".")[0] != name.split(".")[0]
            ]
    groups = strongly_connected(packages)
    assert not groups, "packages of the launch stack import each other: " + "; ".join(
        one_cycle(packages, group) for group in groups
    )


# The floors of the launch stack, for names written as text: a floor may name a module of
# its own floor or one below (launch.frontend finds the front-ends beside it by name), never
# one above it.
LAUNCH_FLOORS = {"ros_tutorials_common": 0, "launch_foundation": 1, "launch": 2, "launch_ros": 2,
                 "launch_xml": 2, "launch_yaml": 2, "launcher": 3}  # fmt: skip


def _docstrings(tree: ast.AST) -> set[int]:
    """The ids of the docstring constants of a module and its classes and functions."""
    found = set()
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        first = body[0] if isinstance(body, list) and body else None
        if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
            found.add(id(first.value))
    return found


def names_of_floors_above(root: Path, floors: dict[str, int]) -> list[str]:
    """Each text in code (not a docstring or comment) of a floor that names a module of a floor
    above it as a dotted path ("launcher.plan" for importlib.import_module): an import the
    graph cannot see."""
    modules = project_modules(root)
    found = []
    for name, source in sorted(modules.items()):
        package = name.split(".")[0]
        if package not in floors:
            continue
        tree = ast.parse(source.read_text(encoding="utf-8"))
        skip = _docstrings(tree)
        for node in ast.walk(tree):
            if not isinstance(node, ast.Constant) or not isinstance(node.value, str):
                continue
            text = node.value
            if id(node) in skip or "." not in text or text not in modules:
                continue
            if floors.get(text.split(".")[0], -1) > floors[package]:
                found.append(f"{source.relative_to(root)}:{node.lineno}: {text!r}")
    return found


def test_the_launch_stack_names_no_floor_above():
    # importlib.import_module("launcher.plan") in launch/ would be an upward import the graph
    # cannot see: a floor finds the one above it only as a plug-in (an entry point).
    found = names_of_floors_above(ROOT, LAUNCH_FLOORS)
    assert not found, "a floor names a module of one above it:\n" + "\n".join(found)


def test_a_module_named_as_text_is_found_but_not_in_a_docstring(tmp_path):
    _write(
        tmp_path,
        {
            "low/__init__.py": '"""Run by high.tool."""\n',
            "low/a.py": 'import importlib\nTOOL = ("high.tool",)\n'
            "def run():\n    return importlib.import_module(TOOL[0])\n",
            "high/__init__.py": "",
            "high/tool.py": "import low.a\n",
        },
    )
    layers = {"low": set(), "high": {"low"}}
    assert names_of_floors_above(tmp_path, {"low": 0, "high": 1}) == ["low/a.py:2: 'high.tool'"]
    assert layer_breaches(tmp_path, layers, set(layers)) == []  # the graph alone misses it


def test_an_upward_import_is_found_even_when_only_for_types(tmp_path):
    _write(
        tmp_path,
        {
            "low/__init__.py": "",
            "low/a.py": "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n"
            "    from high.b import B\n",
            "high/__init__.py": "",
            "high/b.py": "import low.a\nB = 1\n",
            "mid/__init__.py": "",
            "mid/c.py": "def f():\n    import high.b\n",
        },
    )
    layers = {"low": set(), "mid": {"low"}, "high": {"low", "mid"}}
    assert layer_breaches(tmp_path, layers, set(layers)) == [
        "low.a (low/a.py:3) -> high.b",
        "mid.c (mid/c.py:2) -> high.b",
    ]
    assert cycles(tmp_path) == []  # no circle that runs: the type-only import is no edge there


# Which packages a library below the command line may not import (rosbag2's and geometry2's
# layering: the library, then its Python API, then the command line on top).
BELOW_THE_COMMAND_LINE = {
    "rosbag2": ("ros2cmd", "rosbag2_py", "launcher"),
    "rosbag2_py": ("ros2cmd", "launcher"),
}


def test_the_libraries_stand_below_the_command_line():
    graph = import_graph(ROOT)
    assert "rosbag2.reader" in graph and "rosbag2_py._writer" in graph
    upward = [
        f"{name} -> {edge.target} ({edge.where})"
        for name in graph
        for edge in graph[name]
        if edge.target.split(".")[0] in BELOW_THE_COMMAND_LINE.get(name.split(".")[0], ())
    ]
    assert not upward, "a library imports a layer above it:\n" + "\n".join(upward)


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
