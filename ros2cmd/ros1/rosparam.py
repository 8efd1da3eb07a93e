"""`rosparam list|get|set|dump|load`: ROS 1's rosparam on `ros2 param`'s code.

ROS 1 had one global parameter server; ROS 2 has none, every parameter belongs to a node. A
ROS 1 name is looked up: ``/service_server/calculation_method`` names the node; a bare
``/calculation_method`` is found on whichever node declares it (if several do, the command
says so and asks for the node). A node's name, or any namespace of nodes (``/``), stands for
the parameters under it, as in ROS 1's tree: ``rosparam get /service_server``.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph
from ros2cmd.messages import parse_yaml
from ros2cmd.param import api as param
from ros2cmd.ros1 import tool
from ros_tutorials_common import packages
from ros_tutorials_common.shutdown import program_main

# How many running nodes an error names.
NODES_NAMED = 4


def _under(node_name: str, namespace: str) -> bool:
    """Whether a node is in a namespace: '/' holds every node, a node's name holds itself."""
    return namespace == "/" or node_name == namespace or node_name.startswith(namespace + "/")


def resolve_parameter(
    graph: Graph, name: str, namespaces: bool = False
) -> list[tuple[str, str | None]]:
    """A ROS 1 name, waiting for it: '/calculation_method' -> [('/service_server',
    'calculation_method')]; with ``namespaces``, a node's name or a namespace of nodes ('/')
    -> [(node, None), ...], as ROS 1's parameter tree held a node's parameters under it."""
    name = _absolute(name)
    known: dict[str, list[str]] = {}

    def find() -> list[tuple[str, str | None]]:
        nodes = param.nodes_with_parameters(graph)
        if namespaces and (under := [(n, None) for n in nodes if _under(n, name)]):
            return under
        for node_name in sorted(nodes, key=len, reverse=True):
            if name.startswith(node_name + "/"):  # the name says which node
                return [(node_name, name[len(node_name) + 1 :])]
        for node_name in nodes:
            if node_name not in known:
                known[node_name] = param.names(graph, node_name)
        return [(n, name[1:]) for n in nodes if name[1:] in known[n]]

    what = (
        "no node with parameters is running"
        if name == "/"
        else (f"no node declares a parameter '{name[1:]}'")
    )
    try:
        matches = graph.wait_for(find, what)
    except ToolError as error:
        raise ToolError(f"{error}{_not_found_hint(graph, name[1:])}") from None
    if len(matches) > 1 and matches[0][1] is not None:
        holders = ", ".join(node_name for node_name, _ in matches)
        raise ToolError(
            f"parameter '{name[1:]}' is declared by several nodes ({holders}); "
            f"name one, e.g. {matches[0][0]}/{name[1:]}"
        )
    return matches


def _not_found_hint(graph: Graph, name: str) -> str:
    """Which nodes are running, and which executables of this project declare the name."""
    running = graph.node_names()
    shown = ", ".join(running[:NODES_NAMED]) + (
        f" and {len(running) - NODES_NAMED} more" if len(running) > NODES_NAMED else ""
    )
    hint = f"; nodes running: {shown}" if running else "; no node is running"
    declaring = packages.executables_declaring(name) if name and "/" not in name else []
    if declaring:
        runs = " or ".join(f"`rosrun {pkg} {exe}`" for pkg, exe in declaring)
        hint += f"; {runs} declares it"
    return hint


def _value_text(value: Any) -> str:
    import yaml  # where it is used: not to build the parser

    if isinstance(value, (list, dict)):
        return yaml.safe_dump(value, default_flow_style=True).strip()
    return str(value).lower() if isinstance(value, bool) else str(value)


def _absolute(name: str | None) -> str:
    """A ROS 1 name as written ('calculation_method/', '/', None) in its one absolute form."""
    return "/" + (name or "").strip("/")


def rosparam_list(graph: Graph, namespace: str | None = None) -> None:
    """`rosparam list [NAMESPACE]`: /node/parameter names, those under NAMESPACE if given."""
    namespace = _absolute(namespace)
    nodes = [  # ask only the nodes that can hold a name in the namespace
        node_name
        for node_name in param.nodes_with_parameters(graph)
        if _under(node_name, namespace) or namespace.startswith(node_name + "/")
    ]
    answers, silent = param.names_of_each(graph, nodes)
    for node_name in nodes:
        for name in answers.get(node_name, []):
            if _under(f"{node_name}/{name}", namespace):
                print(f"{node_name}/{name}")
    if silent:
        raise param.silent_nodes_error(graph, silent, "above")


def rosparam_get(graph: Graph, name: str) -> None:
    import yaml

    matches = resolve_parameter(graph, name, namespaces=True)
    if matches[0][1] is None:  # a namespace: its nodes' parameters, as a YAML dict
        tree = _parameter_tree(graph, [node_name for node_name, _ in matches], name)
        graph.finish()
        print(yaml.safe_dump(tree, default_flow_style=False).rstrip())
        return
    node_name, param_name = matches[0]
    _, value = param.get_values(graph, node_name, [param_name])[param_name]
    graph.finish()
    print(_value_text(value))


def _parameter_tree(graph: Graph, nodes: list[str], namespace: str) -> dict[str, Any]:
    """{parameter: value} of one node named by its namespace; of several, nested by the
    parts of their names below the namespace ({service_server: {calculation_method: 1}})."""
    namespace = _absolute(namespace)
    tree: dict[str, Any] = {}
    for node_name in nodes:
        values = param.get_values(graph, node_name, param.names(graph, node_name))
        branch = tree
        for part in node_name[len(namespace) :].strip("/").split("/"):
            if part:
                branch = branch.setdefault(part, {})
        branch.update({key: value for key, (_, value) in values.items()})
    return tree


def rosparam_set(graph: Graph, name: str, value: str) -> None:
    matches = resolve_parameter(graph, name, namespaces=True)
    node_name, param_name = matches[0]
    parsed = parse_yaml(value)
    if param_name is not None:
        param.set_values(graph, node_name, {param_name: parsed})
    elif len(matches) == 1 and node_name == _absolute(name) and isinstance(parsed, dict):
        param.set_values(graph, node_name, parsed)  # ROS 1's `rosparam set /node '{a: 1}'`
    else:
        raise ToolError(
            f"{_absolute(name)} is a node's namespace, not a parameter; name one, e.g. "
            f"{node_name}/PARAM (`rosparam list {node_name}` lists them), or set several with "
            f"`rosparam set {node_name} '{{PARAM: VALUE}}'`"
        )


def rosparam_dump(graph: Graph, path: str | None) -> None:
    """Every node's parameters as one params file; a node that does not answer is left out
    and named after the rest is written (exit status 1)."""
    import yaml

    nodes = param.nodes_with_parameters(graph)
    answers, silent = param.names_of_each(graph, nodes)
    data: dict[str, Any] = {}
    for node_name in (n for n in nodes if n in answers):
        data.update(param.dump_data(graph, node_name))
    text = yaml.safe_dump(data, default_flow_style=False)
    if path:
        try:
            Path(path).write_text(text)
        except OSError as error:
            raise ToolError(f"cannot write {path}: {error.strerror}") from None
    else:
        print(text.rstrip())
    if silent:
        raise param.silent_nodes_error(graph, silent, f"from {path}" if path else "above")


def rosparam_load(graph: Graph, path: str) -> None:
    """ROS 1 loaded a file into the one parameter server; here each node it names gets the
    entries that match it (its own, and patterns such as '/**', see ros2cmd/param/api.py)."""
    params_file = param.ParamsFile(path)  # read and checked once, before touching any node
    nodes = list(dict.fromkeys(params_file.node_names()))  # '/ns/node' and 'ns/node' are one
    if not nodes:
        raise ToolError(
            f"{path} names no node, only patterns such as '/**'; use: ros2 param load NODE FILE"
        )
    batches = [(node_name, params_file.params_for(node_name)) for node_name in nodes]
    for node_name, params in batches:
        param.load_params(graph, node_name, params)


def rosparam_parser() -> argparse.ArgumentParser:
    parser, sub, common = tool.new_parser("rosparam", "ROS 1's rosparam, on ROS 2 (ros2 param)")
    name_help = "/node/parameter, or /parameter if one node declares it"

    p = sub.add_parser("list", parents=[common], help="list /node/parameter names")
    p.add_argument("namespace", nargs="?", help="only the names under it (a node: its own)")
    p.set_defaults(run=lambda graph, a: rosparam_list(graph, a.namespace))

    p = sub.add_parser("get", parents=[common], help="print a value")
    p.add_argument("name", help=name_help + "; a node or namespace: all its parameters")
    p.set_defaults(run=lambda graph, a: rosparam_get(graph, a.name))

    p = sub.add_parser("set", parents=[common], help="set a value")
    p.add_argument("name", help=name_help)
    p.add_argument("value", help="a YAML value: 2, 2.5, true, text")
    p.set_defaults(run=lambda graph, a: rosparam_set(graph, a.name, a.value))

    p = sub.add_parser("dump", parents=[common], help="all parameters")
    p.add_argument("file", nargs="?", help="write here instead of printing")
    p.set_defaults(run=lambda graph, a: rosparam_dump(graph, a.file))

    p = sub.add_parser("load", parents=[common], help="set from a dump")
    p.add_argument("file")
    p.set_defaults(run=lambda graph, a: rosparam_load(graph, a.file))
    tool.no_ros2_meaning("rosparam", sub)
    return parser


@program_main  # the console script's entry
def rosparam(argv: Sequence[str] | None = None) -> int:
    return tool.run(rosparam_parser(), argv)
