"""What `ros2 param`'s sub-verbs (verb/) and ROS 1's rosparam (ros1/rosparam.py) share: a
node's parameters through its parameter services, and params files.

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
import re
import sys
import tempfile
import weakref
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph
from ros_tutorials_common.bounded import InputError, parameter_problem, read_params_file

if TYPE_CHECKING:  # rclpy and the messages load when a command runs, not with the parser
    from rcl_interfaces.msg import Parameter as ParameterMsg
    from rcl_interfaces.msg import ParameterValue
    from rclpy.parameter_client import AsyncParameterClient
    from rclpy.task import Future


def parameter_types() -> dict[str, Any]:
    """Each parameter type as `ros2 param describe` and `list --param-type` name it, with
    rclpy's Parameter.Type for it."""
    from rclpy.parameter import Parameter

    kind = Parameter.Type
    return {
        "boolean": kind.BOOL,
        "integer": kind.INTEGER,
        "double": kind.DOUBLE,
        "string": kind.STRING,
        "byte array": kind.BYTE_ARRAY,
        "boolean array": kind.BOOL_ARRAY,
        "integer array": kind.INTEGER_ARRAY,
        "double array": kind.DOUBLE_ARRAY,
        "string array": kind.STRING_ARRAY,
        "not set": kind.NOT_SET,
    }


def described_type(code: int) -> str:
    """How `ros2 param describe` and `list --param-type` name a parameter's type."""
    return next((n for n, kind in parameter_types().items() if kind.value == code), "unknown")


def parameter_value(type_name: str, value: Any) -> ParameterValue:
    """``value`` as the ParameterValue of the type named ``type_name`` (described_type's
    names), filled by rclpy's Parameter: TypeError if it is not of that type, AssertionError
    if the message refuses it (an integer beyond int64)."""
    from rclpy.parameter import Parameter

    return Parameter("value", parameter_types()[type_name], value).get_parameter_value()


# One AsyncParameterClient per (tool run, node): its six service clients live as long as the
# tool's node (rclpy has no call to destroy them earlier).
_clients: weakref.WeakKeyDictionary[Graph, dict[str, AsyncParameterClient]] = (
    weakref.WeakKeyDictionary()
)


def full_node_name(name: str) -> str:
    return "/" + name.strip("/")


def name_matches(key: str, node: str) -> bool:
    """Whether a params file's entry is for ``node`` (a full name), as rcl matches them: a
    leading '/' is implied, '/*' stands for one name part, '/**' for any number of parts."""
    pattern = "".join(
        "(/[^/]+)*" if part == "**" else "/[^/]+" if part == "*" else "/" + re.escape(part)
        for part in key.strip("/").split("/")
    )
    return re.fullmatch(pattern, node) is not None


def ask(graph: Graph, node: str, call: Callable[[AsyncParameterClient], Future]) -> Any:
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
    from rclpy.parameter_client import AsyncParameterClient

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
    response = ask(graph, node, lambda client: client.list_parameters(prefixes=prefixes))
    return sorted(response.result.names)


def get_values(graph: Graph, node: str, params: list[str]) -> dict[str, Any]:
    """{name: (type, python value)} of a node's parameters; an unknown name is a ToolError."""
    from rcl_interfaces.msg import ParameterType
    from rclpy.parameter import parameter_value_to_python

    node = full_node_name(node)
    response = ask(graph, node, lambda client: client.get_parameters(params))
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
        raise ToolError(f"setting '{name}' on {full_node_name(node)} failed: {reason}")


def try_set_values(graph: Graph, node: str, values: dict[str, Any]) -> dict[str, str]:
    """Set parameters on a node, each on its own; return {name: reason} of those refused."""
    for name, value in values.items():
        problem = parameter_problem(name, value)  # e.g. an integer rclpy cannot hold (int64)
        if problem:
            raise ToolError(f"cannot set {problem}")
    from rclpy.parameter import Parameter

    try:
        params = [Parameter(name, value=value).to_parameter_msg() for name, value in values.items()]
    except (TypeError, ValueError) as error:
        raise ToolError(f"cannot use that value as a parameter: {error}") from None
    return _set(graph, node, params)


def _set(graph: Graph, node: str, params: list[ParameterMsg]) -> dict[str, str]:
    return {
        param.name: result.reason
        for param, result in zip(params, set_each(graph, node, params), strict=True)
        if not result.successful
    }


def set_each(graph: Graph, node: str, params: list[ParameterMsg]) -> list[Any]:
    """The node's SetParametersResult for each parameter (each is set on its own)."""
    response = ask(graph, node, lambda client: client.set_parameters(params))
    return list(response.results)


def with_reason(text: str, result: Any) -> str:
    return f"{text}: {result.reason}" if result.reason else text


def load_params(graph: Graph, node: str, params: list[ParameterMsg]) -> None:
    """Set parameters from a params file; like ros2, report refused ones and go on.

    A dump holds read-only parameters too (start_type_description_service), which no node
    accepts at run time; loading that dump back should still set everything else.
    """
    print_loaded(params, set_each(graph, node, params))


def print_loaded(params: list[ParameterMsg], results: list[Any]) -> None:
    """What `ros2 param load` prints: one line per parameter, refused ones on stderr."""
    for param, result in zip(params, results, strict=True):
        # ros2's words; flushed so that the two streams keep their order in a terminal
        if result.successful:
            print(with_reason(f"Set parameter {param.name} successful", result), flush=True)
        else:
            line = with_reason(f"Set parameter {param.name} failed", result)
            print(line, file=sys.stderr, flush=True)


def dump_data(graph: Graph, node: str) -> dict[str, Any]:
    """A node's parameters as a params file holds them: {node: {ros__parameters: {...}}}."""
    node = full_node_name(node)
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
        return [full_node_name(key) for key in self.data if "*" not in key]

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
        import yaml
        from rclpy.parameter import parameter_dict_from_yaml_file

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


def nodes_with_parameters(graph: Graph) -> list[str]:
    """The nodes in the graph that offer parameter services (after discovery settles)."""
    graph.settle()
    services = graph.service_types()
    names = dict.fromkeys(graph.node_names())  # two nodes of one name: list it once
    return [name for name in names if f"{name}/list_parameters" in services]


def add_node_argument(parser: argparse.ArgumentParser, nargs: str | None = None) -> None:
    parser.add_argument("node_name", nargs=nargs, help="Name of the ROS node")
    completion.attach(parser, node_name=completion.node_names)
    # ros2cli's option; this tool's own node is hidden and has no parameter services anyway
    parser.add_argument(
        "--include-hidden-nodes", action="store_true", help="Consider hidden nodes as well"
    )
