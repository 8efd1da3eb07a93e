"""`ros2 param ...`: a node's parameters through its parameter services (like `ros2 param`).

In ROS 2 every parameter belongs to a node, which answers on the services
``<node>/list_parameters``, ``<node>/get_parameters``, ``<node>/set_parameters``,
``<node>/describe_parameters``, ... The calls go through rclpy's own
``AsyncParameterClient``, and params files are read by rclpy's
``parameter_dict_from_yaml_file``, as ``ros2 param`` does. The node checks a new value itself
(its type, its declared range, its own callback), so a refused value comes back with the
node's reason.

A params file gives a node what an rclpy node started with ``--params-file`` takes from it:
every entry whose name matches the node's full name (``/ns/node`` or ``ns/node``; ``/*`` for
one part of a name, ``/**`` for any number, so ``/**`` is every node), in the file's order,
a later entry winning where two set the same parameter.
Before rclpy sees the file it is read within this project's limits (1 MiB, bounded YAML
aliases, see ros_tutorials_common.bounded) and checked (int64, dates, key types); rclpy then
parses a private copy of what was checked. Like ``ros2 param load``, rclpy
types each value from its text, so a quoted ``'5'`` is loaded as the integer 5.
"""

from __future__ import annotations

import argparse
import re
import sys
import tempfile
import weakref
from collections.abc import Callable
from typing import Any

import yaml
from rcl_interfaces.msg import Parameter as ParameterMsg
from rcl_interfaces.msg import ParameterType
from rclpy.parameter import Parameter, parameter_dict_from_yaml_file, parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient
from rclpy.task import Future

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph
from ros2cmd.messages import parse_yaml
from ros_tutorials_common.bounded import InputError, parameter_problem, read_params_file

# How `ros2 param get` names the value types ...
TYPE_NAMES = {
    ParameterType.PARAMETER_BOOL: "Boolean",
    ParameterType.PARAMETER_INTEGER: "Integer",
    ParameterType.PARAMETER_DOUBLE: "Double",
    ParameterType.PARAMETER_STRING: "String",
    ParameterType.PARAMETER_BYTE_ARRAY: "Byte array",
    ParameterType.PARAMETER_BOOL_ARRAY: "Boolean array",
    ParameterType.PARAMETER_INTEGER_ARRAY: "Integer array",
    ParameterType.PARAMETER_DOUBLE_ARRAY: "Double array",
    ParameterType.PARAMETER_STRING_ARRAY: "String array",
}
# ... and how `ros2 param describe` does.
DESCRIBED_TYPES = {code: name.lower() for code, name in TYPE_NAMES.items()}
DESCRIBED_TYPES[ParameterType.PARAMETER_NOT_SET] = "not set"

# One AsyncParameterClient per (tool run, node): its six service clients live as long as the
# tool's node (rclpy has no call to destroy them earlier).
_clients: weakref.WeakKeyDictionary[Graph, dict[str, AsyncParameterClient]] = (
    weakref.WeakKeyDictionary()
)


def _node_name(name: str) -> str:
    return "/" + name.strip("/")


def name_matches(key: str, node: str) -> bool:
    """Whether a params file's entry is for ``node`` (a full name), as rcl matches them: a
    leading '/' is implied, '/*' stands for one name part, '/**' for any number of parts."""
    pattern = "".join(
        "(/[^/]+)*" if part == "**" else "/[^/]+" if part == "*" else "/" + re.escape(part)
        for part in key.strip("/").split("/")
    )
    return re.fullmatch(pattern, node) is not None


def _ask(graph: Graph, node: str, call: Callable[[AsyncParameterClient], Future]) -> Any:
    """Wait for the node and its parameter services, make one call, wait for its answer."""
    node = graph.wait_for_node(node)  # "unknown node '/x'" if it never appears
    clients = _clients.setdefault(graph, {})
    if node not in clients:
        clients[node] = AsyncParameterClient(graph.node, node)
    client = clients[node]
    graph.wait_for(
        client.services_are_ready, f"node '{node}' does not answer: no parameter services"
    )
    future = call(client)
    graph.wait_for(future.done, f"node '{node}' does not answer")
    return future.result()


def names(graph: Graph, node: str) -> list[str]:
    response = _ask(graph, node, lambda client: client.list_parameters())
    return sorted(response.result.names)


def get_values(graph: Graph, node: str, params: list[str]) -> dict[str, Any]:
    """{name: (type, python value)} of a node's parameters; an unknown name is a ToolError."""
    node = _node_name(node)
    response = _ask(graph, node, lambda client: client.get_parameters(params))
    if len(response.values) != len(params):  # rclpy answers nothing for unknown names
        missing = set(params) - set(names(graph, node))
        raise ToolError(f"node '{node}' has no parameter '{', '.join(sorted(missing))}'")
    values = {}
    for name, value in zip(params, response.values, strict=True):
        if value.type == ParameterType.PARAMETER_NOT_SET:
            raise ToolError(f"node '{node}' has no parameter '{name}'")
        values[name] = (value.type, parameter_value_to_python(value))
    return values


def describe(graph: Graph, node: str, params: list[str]) -> list[Any]:
    """The ParameterDescriptors of a node's parameters; an unknown name is a ToolError."""
    get_values(graph, node, params)  # rclpy describes an unknown name as "not set": refuse it
    return list(_ask(graph, node, lambda client: client.describe_parameters(params)).descriptors)


def set_values(graph: Graph, node: str, values: dict[str, Any]) -> None:
    """Set parameters on a node; a value the node refuses is a ToolError with its reason."""
    refused = try_set_values(graph, node, values)
    if refused:
        name, reason = next(iter(refused.items()))
        raise ToolError(f"setting '{name}' on {_node_name(node)} failed: {reason}")


def try_set_values(graph: Graph, node: str, values: dict[str, Any]) -> dict[str, str]:
    """Set parameters on a node, each on its own; return {name: reason} of those refused."""
    for name, value in values.items():
        problem = parameter_problem(name, value)  # e.g. an integer rclpy cannot hold (int64)
        if problem:
            raise ToolError(f"cannot set {problem}")
    try:
        params = [Parameter(name, value=value).to_parameter_msg() for name, value in values.items()]
    except (TypeError, ValueError) as error:
        raise ToolError(f"cannot use that value as a parameter: {error}") from None
    return _set(graph, node, params)


def _set(graph: Graph, node: str, params: list[ParameterMsg]) -> dict[str, str]:
    response = _ask(graph, node, lambda client: client.set_parameters(params))
    return {
        param.name: result.reason
        for param, result in zip(params, response.results, strict=True)
        if not result.successful
    }


def load_file(graph: Graph, node: str, path: str) -> None:
    """Set what a params file gives a node (see the module's docstring)."""
    load_params(graph, node, ParamsFile(path).params_for(_node_name(node)))


def load_params(graph: Graph, node: str, params: list[ParameterMsg]) -> None:
    """Set parameters from a params file; like ros2, report refused ones and go on.

    A dump holds read-only parameters too (start_type_description_service), which no node
    accepts at run time; loading that dump back should still set everything else.
    """
    refused = _set(graph, node, params)
    for param in params:
        if param.name in refused:
            print(f"Set parameter {param.name} failed: {refused[param.name]}", file=sys.stderr)
        else:
            print(f"Set parameter {param.name} successful")


def dump_data(graph: Graph, node: str) -> dict[str, Any]:
    """A node's parameters as a params file holds them: {node: {ros__parameters: {...}}}."""
    node = _node_name(node)
    values = get_values(graph, node, names(graph, node))
    params = {name: value for name, (_, value) in values.items()}
    return {node: {"ros__parameters": params}}


class ParamsFile:
    """A params file, read within the limits and checked, before any node is touched."""

    def __init__(self, path: str) -> None:
        self.path = path
        try:
            self.data = read_params_file(path)  # within the limits, and checked
        except InputError as error:
            raise ToolError(str(error)) from None

    def node_names(self) -> list[str]:
        """The full names of the nodes the file names (not the patterns such as '/**')."""
        return [_node_name(key) for key in self.data if "*" not in key]

    def params_for(self, node: str) -> list[ParameterMsg]:
        """What the file gives ``node`` (a full name): every entry whose name matches it, in
        the file's order, a later one winning where two set a name (by rclpy)."""
        keys = [key for key in self.data if name_matches(key, node)]
        if not keys:
            raise ToolError(f"{self.path} has no entry that matches {node}")
        # rclpy opens the file itself: give it a private copy of what was checked (a named
        # pipe or a file changed meanwhile would be read again, without the limits), each
        # node under its full name (rclpy does not read names written as nested keys).
        with tempfile.NamedTemporaryFile("w", suffix=".yaml", encoding="utf-8") as copy:
            yaml.safe_dump(self.data, copy, sort_keys=False)  # the order decides
            copy.flush()
            try:  # later keys win: the node's own entry overrides the wildcard's
                params = parameter_dict_from_yaml_file(copy.name, target_nodes=keys)
            except (RuntimeError, TypeError, ValueError, AssertionError, yaml.YAMLError) as error:
                reason = " ".join(str(error).split()) or type(error).__name__
                raise ToolError(
                    f"{self.path}: rclpy cannot read the parameters: {reason}"
                ) from None
        return list(params.values())


# The commands as `ros2 param` prints them.


def list_command(graph: Graph, node: str | None) -> None:
    if node:
        for name in names(graph, node):
            print(f"  {name}")
        return
    for full_name in nodes_with_parameters(graph):
        print(f"{full_name}:")
        for name in names(graph, full_name):
            print(f"  {name}")


def nodes_with_parameters(graph: Graph) -> list[str]:
    """The nodes in the graph that offer parameter services (after discovery settles)."""
    graph.settle()
    services = graph.service_types()
    names = dict.fromkeys(graph.node_names())  # two nodes of one name: list it once
    return [name for name in names if f"{name}/list_parameters" in services]


def get_command(graph: Graph, node: str, name: str) -> None:
    param_type, value = get_values(graph, node, [name])[name]
    graph.finish()
    print(f"{TYPE_NAMES.get(param_type, 'Unknown')} value is: {value}")


def describe_command(graph: Graph, node: str, params: list[str]) -> None:
    descriptors = describe(graph, node, params)
    graph.finish()
    for descriptor in descriptors:
        print(f"Parameter name: {descriptor.name}")
        print(f"  Type: {DESCRIBED_TYPES.get(descriptor.type, 'unknown')}")
        if descriptor.description:
            print(f"  Description: {descriptor.description}")
        print("  Constraints:")
        if descriptor.read_only:
            print("    Read only: true")
        ranges = [*descriptor.floating_point_range, *descriptor.integer_range]
        if ranges:
            print(f"    Min value: {ranges[0].from_value}")
            print(f"    Max value: {ranges[0].to_value}")
            if ranges[0].step:
                print(f"    Step: {ranges[0].step}")
        if descriptor.additional_constraints:
            print(f"    Additional constraints: {descriptor.additional_constraints}")


def set_command(graph: Graph, node: str, name: str, value: str) -> None:
    # Read as YAML like ros2 does: 2 is an integer, 2.0 a double, true a boolean, hi a string.
    set_values(graph, node, {name: parse_yaml(value)})
    graph.finish()
    print("Set parameter successful")


def dump_command(graph: Graph, node: str) -> None:
    print(yaml.safe_dump(dump_data(graph, node), default_flow_style=False).rstrip())


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("param", help="parameters: list, get, set, describe, dump, load")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    p = sub.add_parser("list", parents=[common], help="list the parameters of one or all nodes")
    p.add_argument("node", nargs="?")
    p.set_defaults(run=lambda graph, a: list_command(graph, a.node))

    p = sub.add_parser("get", parents=[common], help="print a parameter's value")
    p.add_argument("node")
    p.add_argument("name")
    p.set_defaults(run=lambda graph, a: get_command(graph, a.node, a.name))

    p = sub.add_parser("describe", parents=[common], help="print parameters' types and ranges")
    p.add_argument("node")
    p.add_argument("names", nargs="+")
    p.set_defaults(run=lambda graph, a: describe_command(graph, a.node, a.names))

    p = sub.add_parser("set", parents=[common], help="set a parameter (value as YAML)")
    p.add_argument("node")
    p.add_argument("name")
    p.add_argument("value")
    p.set_defaults(run=lambda graph, a: set_command(graph, a.node, a.name, a.value))

    p = sub.add_parser("dump", parents=[common], help="print a node's parameters as a params file")
    p.add_argument("node")
    p.set_defaults(run=lambda graph, a: dump_command(graph, a.node))

    p = sub.add_parser("load", parents=[common], help="set a node's parameters from a params file")
    p.add_argument("node")
    p.add_argument("file")
    p.set_defaults(run=lambda graph, a: load_file(graph, a.node, a.file))
