"""`ros2 param ...` (list, get, set, delete, describe, dump, load): a node's parameters
through its parameter services, printed as ROS 2 Jazzy's ros2param prints them
(`Integer value is: 86`, `Set parameter successful`, the dump's `/node:` /
`  ros__parameters:` YAML). The ROS 1 front-end (ros1/rosparam.py) uses the same functions.

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
import contextlib
import os
import re
import sys
import tempfile
import weakref
from collections.abc import Callable
from typing import Any

import yaml
from rcl_interfaces.msg import Parameter as ParameterMsg
from rcl_interfaces.msg import ParameterType, ParameterValue
from rclpy.parameter import (
    PARAMETER_SEPARATOR_STRING,
    Parameter,
    parameter_dict_from_yaml_file,
    parameter_value_to_python,
)
from rclpy.parameter_client import AsyncParameterClient
from rclpy.task import Future

from ros2cmd.errors import ToolError, ToolFailure
from ros2cmd.graph import Graph, split_node_name
from ros2cmd.messages import parse_yaml
from ros_tutorials_common.bounded import InputError, parameter_problem, read_params_file

# How `ros2 param describe` and `list --param-type` name the types ...
DESCRIBED_TYPES = {
    ParameterType.PARAMETER_BOOL: "boolean",
    ParameterType.PARAMETER_INTEGER: "integer",
    ParameterType.PARAMETER_DOUBLE: "double",
    ParameterType.PARAMETER_STRING: "string",
    ParameterType.PARAMETER_BYTE_ARRAY: "byte array",
    ParameterType.PARAMETER_BOOL_ARRAY: "boolean array",
    ParameterType.PARAMETER_INTEGER_ARRAY: "integer array",
    ParameterType.PARAMETER_DOUBLE_ARRAY: "double array",
    ParameterType.PARAMETER_STRING_ARRAY: "string array",
    ParameterType.PARAMETER_NOT_SET: "not set",
}
# ... and how `ros2 param get` introduces a value of each.
GET_LABELS = {
    ParameterType.PARAMETER_BOOL: "Boolean value is:",
    ParameterType.PARAMETER_INTEGER: "Integer value is:",
    ParameterType.PARAMETER_DOUBLE: "Double value is:",
    ParameterType.PARAMETER_STRING: "String value is:",
    ParameterType.PARAMETER_BYTE_ARRAY: "Byte values are:",
    ParameterType.PARAMETER_BOOL_ARRAY: "Boolean values are:",
    ParameterType.PARAMETER_INTEGER_ARRAY: "Integer values are:",
    ParameterType.PARAMETER_DOUBLE_ARRAY: "Double values are:",
    ParameterType.PARAMETER_STRING_ARRAY: "String values are:",
}

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
    client = _client(graph, node)
    graph.wait_for(
        client.services_are_ready, f"node '{node}' does not answer: no parameter services"
    )
    future = call(client)
    graph.wait_for(future.done, f"node '{node}' does not answer")
    return future.result()


def _client(graph: Graph, node: str) -> AsyncParameterClient:
    clients = _clients.setdefault(graph, {})
    if node not in clients:
        clients[node] = AsyncParameterClient(graph.node, node)
    return clients[node]


def names_of_each(
    graph: Graph, nodes: list[str], prefixes: list[str] | None = None
) -> tuple[dict[str, list[str]], list[str]]:
    """Each node's parameter names, asked of all the nodes at once: ({node: names} of those
    that answered within --timeout, [those that did not]). One slow or stuck node costs one
    wait, and the others' answers are kept (a stuck node made `rosparam list` print nothing)."""
    clients = {node: _client(graph, node) for node in nodes}
    futures: dict[str, Future] = {}

    def all_answered() -> bool:
        for node, client in clients.items():
            if node not in futures and client.services_are_ready():
                futures[node] = client.list_parameters(prefixes=prefixes)
        return len(futures) == len(clients) and all(f.done() for f in futures.values())

    with contextlib.suppress(ToolError):  # after --timeout: what did answer
        graph.wait_for(all_answered, "")
    answers = {
        node: sorted(future.result().result.names)
        for node, future in futures.items()
        if future.done() and future.result() is not None
    }
    return answers, [node for node in nodes if node not in answers]


def silent_nodes_error(graph: Graph, silent: list[str], where: str) -> ToolError:
    """The error for nodes that did not answer, once the others' answers are out."""
    quoted = ", ".join(f"'{node}'" for node in silent)
    nodes = "node" if len(silent) == 1 else "nodes"
    return ToolError(
        f"no answer from {nodes} {quoted} within {graph.timeout:g} s: "
        f"{'its' if len(silent) == 1 else 'their'} parameters are missing {where}"
    )


def names(graph: Graph, node: str, prefixes: list[str] | None = None) -> list[str]:
    """A node's parameter names, sorted; only those under ``prefixes`` if given."""
    response = _ask(graph, node, lambda client: client.list_parameters(prefixes=prefixes))
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
    return {
        param.name: result.reason
        for param, result in zip(params, _set_each(graph, node, params), strict=True)
        if not result.successful
    }


def _set_each(graph: Graph, node: str, params: list[ParameterMsg]) -> list[Any]:
    """The node's SetParametersResult for each parameter (each is set on its own)."""
    response = _ask(graph, node, lambda client: client.set_parameters(params))
    return list(response.results)


def _with_reason(text: str, result: Any) -> str:
    return f"{text}: {result.reason}" if result.reason else text


def load_file(graph: Graph, node: str, path: str, use_wildcard: bool = True) -> None:
    """`ros2 param load`: set what a params file gives a node (see the module's docstring)."""
    params = ParamsFile(path).params_for(_node_name(node), use_wildcard)
    results = _set_each(graph, node, params)
    graph.finish()
    print_loaded(params, results)


def load_params(graph: Graph, node: str, params: list[ParameterMsg]) -> None:
    """Set parameters from a params file; like ros2, report refused ones and go on.

    A dump holds read-only parameters too (start_type_description_service), which no node
    accepts at run time; loading that dump back should still set everything else.
    """
    print_loaded(params, _set_each(graph, node, params))


def print_loaded(params: list[ParameterMsg], results: list[Any]) -> None:
    """What `ros2 param load` prints: one line per parameter, refused ones on stderr."""
    for param, result in zip(params, results, strict=True):
        # ros2's words; flushed so that the two streams keep their order in a terminal
        if result.successful:
            print(_with_reason(f"Set parameter {param.name} successful", result), flush=True)
        else:
            line = _with_reason(f"Set parameter {param.name} failed", result)
            print(line, file=sys.stderr, flush=True)


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

    def params_for(self, node: str, use_wildcard: bool = True) -> list[ParameterMsg]:
        """What the file gives ``node`` (a full name): every entry whose name matches it, in
        the file's order, a later one winning where two set a name (by rclpy). Without
        ``use_wildcard``, only the entries that name the node (no '/**' or '/*')."""
        keys = [
            key for key in self.data if name_matches(key, node) and (use_wildcard or "*" not in key)
        ]
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


# The commands, as `ros2 param` (ros2param, Jazzy) prints them.


def _listing_order(full_name: str) -> tuple[str, str, str]:
    # ros2param sorts its NodeName tuples: by the node's own name, then its namespace.
    namespace, name = split_node_name(full_name)
    return name, namespace, full_name


def list_command(
    graph: Graph,
    node: str | None,
    prefixes: list[str] | None = None,
    with_types: bool = False,
    pattern: str | None = None,
) -> None:
    """`ros2 param list [NODE]`: every node's name then its parameters, or only NODE's
    parameters (no heading), each indented by two spaces."""
    try:
        regex = re.compile(pattern) if pattern is not None else None
    except re.error as error:
        raise ToolError(f"invalid --filter regular expression {pattern!r}: {error}") from None
    silent: list[str] = []
    if node:
        nodes = [graph.wait_for_node(node)]
        answers = {nodes[0]: names(graph, nodes[0], prefixes or None)}
    else:
        nodes = sorted(nodes_with_parameters(graph), key=_listing_order)
        answers, silent = names_of_each(graph, nodes, prefixes or None)
    listing = []
    for full_name in (n for n in nodes if n in answers):
        found = answers[full_name]
        if regex is not None:
            found = [name for name in found if regex.match(name)]
        types = {}
        if with_types and found:
            descriptors = _ask(
                graph, full_name, lambda client, f=found: client.describe_parameters(f)
            )
            types = {
                d.name: DESCRIBED_TYPES.get(d.type, "unknown") for d in descriptors.descriptors
            }
        listing.append((full_name, found, types))
    if not silent:
        graph.finish()
    for full_name, found, types in listing:
        if not node and found:
            print(f"{full_name}:")
        for name in found:
            print(f"  {name} (type: {types[name]})" if with_types else f"  {name}")
    if silent:
        raise silent_nodes_error(graph, silent, "above")


def nodes_with_parameters(graph: Graph) -> list[str]:
    """The nodes in the graph that offer parameter services (after discovery settles)."""
    graph.settle()
    services = graph.service_types()
    names = dict.fromkeys(graph.node_names())  # two nodes of one name: list it once
    return [name for name in names if f"{name}/list_parameters" in services]


def get_command(graph: Graph, node: str, name: str, hide_type: bool = False) -> None:
    param_type, value = get_values(graph, node, [name])[name]
    graph.finish()
    if hide_type:
        print(value)
    else:
        print(GET_LABELS.get(param_type, f"Unknown parameter type '{param_type}'"), value)


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


def typed_value(name: str, text: str) -> ParameterValue:
    """The value `ros2 param set` sends for what was typed: typed as YAML reads it, as
    rclpy's get_parameter_value does (2 an integer, 2.0 a double, true a boolean, a list of
    one of those an array); anything else, a mixed list or a mapping too, is the text itself.
    """
    try:
        value = parse_yaml(text)
    except ToolError:  # not YAML (`a: b: c`): the text, as rclpy does
        value = text
    for item in value if isinstance(value, list) else [value]:
        if isinstance(item, int) and (problem := parameter_problem(name, item)):
            raise ToolError(f"cannot set {problem}")  # beyond int64: rclpy fails an assert
    if isinstance(value, bool):
        return ParameterValue(type=ParameterType.PARAMETER_BOOL, bool_value=value)
    if isinstance(value, int):
        return ParameterValue(type=ParameterType.PARAMETER_INTEGER, integer_value=value)
    if isinstance(value, float):
        return ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=value)
    if isinstance(value, list):
        for kind, code, field in (
            (bool, ParameterType.PARAMETER_BOOL_ARRAY, "bool_array_value"),
            (int, ParameterType.PARAMETER_INTEGER_ARRAY, "integer_array_value"),
            (float, ParameterType.PARAMETER_DOUBLE_ARRAY, "double_array_value"),
            (str, ParameterType.PARAMETER_STRING_ARRAY, "string_array_value"),
        ):
            # rclpy's tests in its order: [] is a boolean array, [1, true] no integer array
            if all(
                isinstance(item, kind) and (kind is bool) == isinstance(item, bool)
                for item in value
            ):
                return ParameterValue(type=code, **{field: value})
    text_value = value if isinstance(value, str) else text
    return ParameterValue(type=ParameterType.PARAMETER_STRING, string_value=text_value)


def set_command(graph: Graph, node: str, name: str, text: str) -> None:
    """`ros2 param set`: the node's answer in ros2's words; a refusal is exit status 1."""
    value = typed_value(name, text)
    node = graph.wait_for_node(node)
    result = _set_each(graph, node, [ParameterMsg(name=name, value=value)])[0]
    if not result.successful:
        raise ToolFailure(_with_reason("Setting parameter failed", result))
    graph.finish()
    print(_with_reason("Set parameter successful", result))


def delete_command(graph: Graph, node: str, name: str) -> None:
    """`ros2 param delete`: set to 'not set', which undeclares it where the node allows."""
    node = graph.wait_for_node(node)
    unset = ParameterValue(type=ParameterType.PARAMETER_NOT_SET)
    result = _set_each(graph, node, [ParameterMsg(name=name, value=unset)])[0]
    if not result.successful:
        raise ToolFailure(_with_reason("Deleting parameter failed", result))
    graph.finish()
    print(_with_reason("Deleted parameter successfully", result))


def dump_text(graph: Graph, node: str) -> str:
    """A node's parameters as `ros2 param dump` writes them: /node: / ros__parameters:,
    the names sorted, nested at each '.' (qos_overrides./parameter_events.publisher.depth)."""
    node = _node_name(node)
    values = get_values(graph, node, names(graph, node))
    tree: dict[str, Any] = {}
    for name, (_, value) in values.items():
        *parents, leaf = name.split(PARAMETER_SEPARATOR_STRING)
        branch = tree
        for part in parents:
            branch = branch.setdefault(part, {})
        branch[leaf] = value
    return yaml.safe_dump({node: {"ros__parameters": tree}}, default_flow_style=False)


def dump_command(graph: Graph, node: str, output_dir: str | None = None) -> None:
    """`ros2 param dump NODE`: the YAML on stdout (`> file.yaml` saves it). --output-dir is
    Humble's deprecated spelling (gone in Jazzy): it still writes DIR/NODE.yaml, with
    Humble's warning."""
    if output_dir is not None and output_dir != "." and not os.path.isdir(output_dir):
        raise ToolError(f"'{output_dir}' is not a valid directory.")
    text = dump_text(graph, node)
    graph.finish()
    if output_dir is None or output_dir == ".":
        print(text)  # ros2 prints the YAML and a newline: one blank line at the end
        return
    print(
        "WARNING: '--output-dir' is deprecated; use redirection to save to a file",
        file=sys.stderr,
    )
    path = os.path.join(output_dir, _node_name(node)[1:].replace("/", "__") + ".yaml")
    print("Saving to: ", path)
    try:
        with open(path, "w", encoding="utf-8") as file:
            file.write(text)
    except OSError as error:
        raise ToolError(f"cannot write {path}: {error.strerror}") from None


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("param", help="Various param related sub-commands")
    sub = parser.add_subparsers(dest="command", metavar="Commands", required=True)

    p = sub.add_parser("delete", parents=[common], help="Delete parameter")
    _node_argument(p)
    p.add_argument("parameter_name", help="Name of the parameter")
    p.set_defaults(run=lambda graph, a: delete_command(graph, a.node_name, a.parameter_name))

    p = sub.add_parser(
        "describe", parents=[common], help="Show descriptive information about declared parameters"
    )
    _node_argument(p)
    p.add_argument("parameter_names", nargs="+", help="Names of the parameters")
    p.set_defaults(run=lambda graph, a: describe_command(graph, a.node_name, a.parameter_names))

    p = sub.add_parser(
        "dump", parents=[common], help="Show all of the parameters of a node in a YAML file format"
    )
    _node_argument(p)
    p.add_argument("--output-dir", help="DEPRECATED: where to save NODE.yaml; use > FILE")
    p.set_defaults(run=lambda graph, a: dump_command(graph, a.node_name, a.output_dir))

    p = sub.add_parser("get", parents=[common], help="Get parameter")
    _node_argument(p)
    p.add_argument("parameter_name", help="Name of the parameter")
    p.add_argument("--hide-type", action="store_true", help="Hide the type information")
    p.set_defaults(
        run=lambda graph, a: get_command(graph, a.node_name, a.parameter_name, a.hide_type)
    )

    p = sub.add_parser("list", parents=[common], help="Output a list of available parameters")
    _node_argument(p, nargs="?")
    p.add_argument(
        "--filter",
        metavar="REGEX",
        help="Only parameters matching the regex expression will be showed. "
        "Supports `re` regex syntax.",
    )
    p.add_argument(
        "--param-prefixes",
        nargs="+",
        default=[],
        help="Only list parameters with the provided prefixes",
    )
    p.add_argument(
        "--param-type", action="store_true", help="Print parameter types with parameter names"
    )
    p.set_defaults(
        run=lambda graph, a: list_command(
            graph, a.node_name, a.param_prefixes, a.param_type, a.filter
        )
    )

    p = sub.add_parser("load", parents=[common], help="Load parameter file for a node")
    _node_argument(p)
    p.add_argument("parameter_file", help="Parameter file")
    p.add_argument(
        "--no-use-wildcard",
        action="store_true",
        help="Do not load parameters in the '/**' namespace into the node",
    )
    p.set_defaults(
        run=lambda graph, a: load_file(graph, a.node_name, a.parameter_file, not a.no_use_wildcard)
    )

    p = sub.add_parser("set", parents=[common], help="Set parameter")
    _node_argument(p)
    p.add_argument("parameter_name", help="Name of the parameter")
    p.add_argument("value", help="Value of the parameter")
    p.set_defaults(run=lambda graph, a: set_command(graph, a.node_name, a.parameter_name, a.value))


def _node_argument(parser: argparse.ArgumentParser, nargs: str | None = None) -> None:
    parser.add_argument("node_name", nargs=nargs, help="Name of the ROS node")
    # ros2cli's option; this tool's own node is hidden and has no parameter services anyway
    parser.add_argument(
        "--include-hidden-nodes", action="store_true", help="Consider hidden nodes as well"
    )
