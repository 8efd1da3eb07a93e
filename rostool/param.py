"""`rostool param ...`: a node's parameters through its parameter services (like `ros2 param`).

In ROS 2 every parameter belongs to a node, which answers on the services
``<node>/list_parameters``, ``<node>/get_parameters`` and ``<node>/set_parameters``.
The node checks a new value itself (its type, its declared range, its own callback), so a
refused value comes back with the node's reason.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

import yaml
from rcl_interfaces.msg import ParameterType
from rcl_interfaces.srv import GetParameters, ListParameters, SetParameters
from rclpy.parameter import Parameter, parameter_value_to_python

from ros_tutorials_common.bounded import (
    InputError,
    load_yaml_file,
    parameter_problem,
    parameters_problem,
)
from rostool.errors import ToolError
from rostool.graph import Graph
from rostool.messages import parse_yaml

# How `ros2 param get` names the value types.
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


def _node_name(name: str) -> str:
    return "/" + name.strip("/")


def _call(graph: Graph, node: str, srv_type: type, service: str, request: Any) -> Any:
    graph.wait_for_node(node)
    client = graph.node.create_client(srv_type, f"{node}/{service}")
    try:
        return graph.call(client, request, f"node '{node}' does not answer")
    finally:
        graph.node.destroy_client(client)


def names(graph: Graph, node: str) -> list[str]:
    node = _node_name(node)
    response = _call(graph, node, ListParameters, "list_parameters", ListParameters.Request())
    return sorted(response.result.names)


def get_values(graph: Graph, node: str, params: list[str]) -> dict[str, Any]:
    """{name: python value} of a node's parameters; an unknown name is a ToolError."""
    node = _node_name(node)
    request = GetParameters.Request(names=params)
    response = _call(graph, node, GetParameters, "get_parameters", request)
    if len(response.values) != len(params):  # rclpy answers nothing for unknown names
        missing = set(params) - set(names(graph, node))
        raise ToolError(f"node '{node}' has no parameter '{', '.join(sorted(missing))}'")
    values = {}
    for name, value in zip(params, response.values, strict=True):
        if value.type == ParameterType.PARAMETER_NOT_SET:
            raise ToolError(f"node '{node}' has no parameter '{name}'")
        values[name] = (value.type, parameter_value_to_python(value))
    return values


def set_values(graph: Graph, node: str, values: dict[str, Any]) -> None:
    """Set parameters on a node; a value the node refuses is a ToolError with its reason."""
    refused = try_set_values(graph, node, values)
    if refused:
        name, reason = next(iter(refused.items()))
        raise ToolError(f"setting '{name}' on {_node_name(node)} failed: {reason}")


def try_set_values(graph: Graph, node: str, values: dict[str, Any]) -> dict[str, str]:
    """Set parameters on a node, each on its own; return {name: reason} of those refused."""
    node = _node_name(node)
    for name, value in values.items():
        problem = parameter_problem(name, value)  # e.g. an integer rclpy cannot hold (int64)
        if problem:
            raise ToolError(f"cannot set {problem}")
    try:
        params = [Parameter(name, value=value).to_parameter_msg() for name, value in values.items()]
    except (TypeError, ValueError) as error:
        raise ToolError(f"cannot use that value as a parameter: {error}") from None
    request = SetParameters.Request(parameters=params)
    response = _call(graph, node, SetParameters, "set_parameters", request)
    return {
        name: result.reason
        for name, result in zip(values, response.results, strict=True)
        if not result.successful
    }


def load_file(graph: Graph, node: str, path: str) -> None:
    """Set what a params file gives a node (see load_values)."""
    load_values(graph, node, params_for_node(read_params_file(path), path, _node_name(node)))


def load_values(graph: Graph, node: str, values: dict[str, Any]) -> None:
    """Set parameters from a params file; like ros2, report refused ones and go on.

    A dump holds read-only parameters too (start_type_description_service), which no node
    accepts at run time; loading that dump back should still set everything else.
    """
    refused = try_set_values(graph, node, values)
    for name in values:
        if name in refused:
            print(f"Set parameter {name} failed: {refused[name]}", file=sys.stderr)
        else:
            print(f"Set parameter {name} successful")


def dump_data(graph: Graph, node: str) -> dict[str, Any]:
    """A node's parameters as a params file holds them: {node: {ros__parameters: {...}}}."""
    node = _node_name(node)
    values = get_values(graph, node, names(graph, node))
    params = {name: value for name, (_, value) in values.items()}
    return {node: {"ros__parameters": params}}


def read_params_file(path: str) -> dict[Any, Any]:
    """The mapping a params file holds; a missing, unreadable or malformed file is a ToolError."""
    try:
        data = load_yaml_file(path)  # at most 1 MiB, UTF-8, bounded aliases
    except InputError as error:
        raise ToolError(str(error)) from None
    except yaml.YAMLError as error:
        raise ToolError(f"{path} is not valid YAML: {str(error).splitlines()[0]}") from None
    if not isinstance(data, dict):
        raise ToolError(f"{path} is not a parameters file (expected 'node: ros__parameters: ...')")
    for key, entry in data.items():  # checked before any node is touched
        problem = parameters_problem({key: entry})
        if problem:
            raise ToolError(f"{path}: {problem}")
    return data


def params_for_node(data: dict[Any, Any], path: str, node: str) -> dict[str, Any]:
    """The parameters a params file gives a node: its entry, '/**' entries, or the only one."""
    found: dict[str, Any] = {}
    for key, entry in data.items():
        key = str(key)
        if key in ("/**", node, node.lstrip("/")) and isinstance(entry, dict):
            found.update(_flatten(entry.get("ros__parameters") or {}))
    if not found:
        raise ToolError(f"{path} has no parameters for {node} (nor for /**)")
    return found


def _flatten(params: dict[str, Any], prefix: str = "") -> dict[str, Any]:
    """Nested YAML mappings are dotted parameter names: {a: {b: 1}} -> {'a.b': 1}."""
    flat = {}
    for name, value in params.items():
        if isinstance(value, dict):
            flat.update(_flatten(value, f"{prefix}{name}."))
        else:
            flat[f"{prefix}{name}"] = value
    return flat


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
    return [name for name in graph.node_names() if f"{name}/list_parameters" in services]


def get_command(graph: Graph, node: str, name: str) -> None:
    param_type, value = get_values(graph, node, [name])[name]
    graph.finish()
    print(f"{TYPE_NAMES.get(param_type, 'Unknown')} value is: {value}")


def set_command(graph: Graph, node: str, name: str, value: str) -> None:
    # Read as YAML like ros2 does: 2 is an integer, 2.0 a double, true a boolean, hi a string.
    set_values(graph, node, {name: parse_yaml(value)})
    graph.finish()
    print("Set parameter successful")


def dump_command(graph: Graph, node: str) -> None:
    print(yaml.safe_dump(dump_data(graph, node), default_flow_style=False).rstrip())


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("param", help="parameters: list, get, set, dump, load")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    p = sub.add_parser("list", parents=[common], help="list the parameters of one or all nodes")
    p.add_argument("node", nargs="?")
    p.set_defaults(run=lambda graph, a: list_command(graph, a.node))

    p = sub.add_parser("get", parents=[common], help="print a parameter's value")
    p.add_argument("node")
    p.add_argument("name")
    p.set_defaults(run=lambda graph, a: get_command(graph, a.node, a.name))

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
