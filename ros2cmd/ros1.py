"""The ROS 1 spellings: rostopic, rosservice, rosparam, rosnode, rosmsg, rossrv.

The seeds' commands work as printed (``rosservice call /ros_tutorial_srv 10 5``,
``rosparam set /calculation_method 2``) and run the same code as ``ros2``. Two ROS 1
habits need translating:

- Values by position: ``rosservice call /srv 10 5`` fills the request's fields in order.
- One global parameter server: ROS 2 has none, every parameter belongs to a node. A ROS 1
  name is looked up: ``/service_server/calculation_method`` names the node; a bare
  ``/calculation_method`` is found on whichever node declares it (if several do, the
  command says so and asks for the node). A node's name, or any namespace of nodes (``/``),
  stands for the parameters under it, as in ROS 1's tree: ``rosparam get /service_server``.

Commands with no ROS 2 meaning (``rosnode kill``, ``rosservice uri``, ...) say so in one
line and name the ROS 2 way.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import yaml

from launcher import packages
from ros2cmd import interface, node, param, service, topic
from ros2cmd.cli import common_options, run_parsed
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name
from ros2cmd.messages import parse_yaml
from ros2cmd.typenames import load_type
from ros_tutorials_common.cli import positive_int, positive_rate
from ros_tutorials_common.ctrl_c import exits_130_on_ctrl_c

# ROS 1 commands that have no ROS 2 counterpart, and what to do instead.
NO_ROS2_MEANING = {
    ("rosnode", "kill"): "ROS 2 has no master to kill nodes through; stop the node's process "
    "(Ctrl-C in its terminal or the launcher's, or `kill PID`)",
    ("rosnode", "ping"): "ROS 2 nodes have no XML-RPC address to ping; `rosnode info NODE` "
    "shows whether the node is in the graph",
    ("rosnode", "machine"): "ROS 2 does not record which machine a node runs on; "
    "`rosnode list` (or `ros2 node list`) shows every node in the graph",
    ("rosnode", "cleanup"): "ROS 2 has no master registry to clean; DDS drops vanished nodes "
    "by itself, and `rosnode list` shows the ones still there",
    ("rosservice", "uri"): "ROS 2 services have no ROSRPC URI (they travel over DDS); "
    "`rosservice info SERVICE` shows the node that serves it and its type",
    ("rosparam", "delete"): "a ROS 2 parameter belongs to its node and stays declared; set "
    "another value with `rosparam set`",
    ("rosmsg", "md5"): "ROS 2 types have no MD5 sum; `rosmsg show` gives the definition",
    ("rossrv", "md5"): "ROS 2 types have no MD5 sum; `rossrv show` gives the definition",
    ("rosmsg", "users"): "ROS 2 keeps no index of the code that uses a type; "
    "`rostopic find TYPE` (or `ros2 topic find TYPE`) lists the topics that carry it",
    ("rossrv", "users"): "ROS 2 keeps no index of the code that uses a type; "
    "`rosservice find TYPE` (or `ros2 service find TYPE`) lists the services that use it",
}


def values_from_args(args: Sequence[str]) -> Any:
    """ROS 1 values: one YAML mapping (`'{a: 1}'`), or field values in order (`10 5`)."""
    # An empty argument ("" in the shell) is an empty string, as in ROS 1
    # (`rosservice call /spawn 3 3 0.2 ""` lets turtlesim pick the name), not YAML's null.
    values = [parse_yaml(arg) if arg else "" for arg in args]
    if not values:
        return None
    if len(values) == 1 and isinstance(values[0], dict):
        return values[0]
    return values


# rosparam: ROS 1 names onto (node, parameter), or onto the nodes of a namespace.

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
    entries that match it (its own, and patterns such as '/**', see ros2cmd.param)."""
    params_file = param.ParamsFile(path)  # read and checked once, before touching any node
    nodes = list(dict.fromkeys(params_file.node_names()))  # '/ns/node' and 'ns/node' are one
    if not nodes:
        raise ToolError(
            f"{path} names no node, only patterns such as '/**'; use: ros2 param load NODE FILE"
        )
    batches = [(node_name, params_file.params_for(node_name)) for node_name in nodes]
    for node_name, params in batches:
        param.load_params(graph, node_name, params)


# The tools. Each is a parser whose commands call the ros2 functions, built as the ros2
# verbs build theirs (topic.register, ...): one sub-parser per command, its `run` a default.


def _parser(tool: str, description: str) -> tuple[argparse.ArgumentParser, Any, Any]:
    parser = argparse.ArgumentParser(prog=tool, description=description)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    parser.set_defaults(commands=sub.choices)  # for _run
    return parser, sub, common_options()


def _no_meaning(tool: str, sub: Any) -> None:
    for (owner, command), reason in NO_ROS2_MEANING.items():
        if owner == tool:
            p = sub.add_parser(command, help="(no ROS 2 counterpart)")
            p.add_argument("rest", nargs="*")
            p.set_defaults(offline=True, run=_refuse(f"{tool} {command}", reason))


def _refuse(command: str, reason: str) -> Callable:
    def run(_graph: Graph | None, _args: argparse.Namespace) -> None:
        raise ToolError(f"`{command}` has no ROS 2 meaning: {reason}")

    return run


def rostopic_parser() -> argparse.ArgumentParser:
    parser, sub, common = _parser("rostopic", "ROS 1's rostopic, on ROS 2 (see: ros2 topic)")

    p = sub.add_parser("list", parents=[common], help="list topics")
    p.add_argument("-v", "--verbose", action="store_true", help="with types")
    p.set_defaults(run=lambda graph, a: topic.list_topics(graph, a.verbose))

    p = sub.add_parser("echo", parents=[common], help="print messages")
    p.add_argument("topic", help="a topic, or /topic/field for one field (/t/stamp/sec)")
    p.add_argument("-n", type=positive_int, help="print this many messages, then exit")
    p.set_defaults(run=lambda graph, a: topic.echo(graph, a.topic, count=a.n, field_in_name=True))

    p = sub.add_parser("pub", parents=[common], help="publish a message")
    p.add_argument("topic")
    p.add_argument("type")
    p.add_argument("values", nargs="*", help="a YAML mapping, or field values in order")
    group = p.add_mutually_exclusive_group()  # ROS 1 refused both too
    group.add_argument("-r", "--rate", type=positive_rate, help="publish at this rate until Ctrl-C")
    group.add_argument("-1", "--once", action="store_true", help="publish once, then exit")
    p.add_argument("-v", "--verbose", action="store_true", help="print each message (with -r)")
    p.set_defaults(run=_pub)

    for name, bandwidth in (("hz", False), ("bw", True)):
        p = sub.add_parser(name, parents=[common], help="")
        p.add_argument("topic")
        p.set_defaults(run=lambda graph, a, b=bandwidth: topic.hz(graph, a.topic, 10000, b))

    p = sub.add_parser("info", parents=[common], help="publishers etc.")
    p.add_argument("topic")
    p.set_defaults(run=lambda graph, a: topic.info(graph, a.topic, True))

    p = sub.add_parser("type", parents=[common], help="message type")
    p.add_argument("topic")
    p.set_defaults(run=lambda graph, a: topic.print_type(graph, a.topic))

    p = sub.add_parser("find", parents=[common], help="topics of a type")
    p.add_argument("type")
    p.set_defaults(run=lambda graph, a: topic.find(graph, a.type))
    return parser


def _pub(graph: Graph, args: argparse.Namespace) -> None:
    values = values_from_args(args.values)
    if args.rate is not None:
        topic.pub(graph, args.topic, args.type, values, rate=args.rate, verbose=args.verbose)
    elif args.once:
        topic.pub(graph, args.topic, args.type, values, times=1)
    else:  # ROS 1's default: publish once, latched, until Ctrl-C
        topic.pub(graph, args.topic, args.type, values, rate=None, latch=True)


def rosservice_parser() -> argparse.ArgumentParser:
    parser, sub, common = _parser("rosservice", "ROS 1's rosservice, on ROS 2 (ros2 service)")

    p = sub.add_parser("list", parents=[common], help="list services")
    p.set_defaults(run=lambda graph, a: service.list_services(graph))

    p = sub.add_parser("type", parents=[common], help="service type")
    p.add_argument("service")
    p.set_defaults(run=lambda graph, a: service.print_type(graph, a.service))

    p = sub.add_parser("call", parents=[common], help="call a service")
    p.add_argument("service")
    p.add_argument("values", nargs="*", help="a YAML mapping, or field values in order")
    p.set_defaults(run=_call)

    p = sub.add_parser("args", parents=[common], help="request fields")
    p.add_argument("service")
    p.set_defaults(run=lambda graph, a: _service_args(graph, a.service))

    p = sub.add_parser("info", parents=[common], help="node, type, args")
    p.add_argument("service")
    p.set_defaults(run=lambda graph, a: _service_info(graph, a.service))

    p = sub.add_parser("find", parents=[common], help="services of a type")
    p.add_argument("type")
    p.set_defaults(run=lambda graph, a: service.find(graph, a.type))
    _no_meaning("rosservice", sub)
    return parser


def _call(graph: Graph, args: argparse.Namespace) -> None:
    values = values_from_args(args.values)
    if values is None:  # ROS 1 refused a call without its values: no silent default request
        values = []
    service.call(graph, args.service, None, values, ros1_output=True)


def _request_fields(graph: Graph, name: str) -> tuple[str, list[str]]:
    type_name = graph.wait_for_service_type(absolute_name(name))
    fields = load_type(type_name, ("srv",)).Request.get_fields_and_field_types()
    return type_name, list(fields)


def _service_args(graph: Graph, name: str) -> None:
    print(" ".join(_request_fields(graph, name)[1]))


def _service_info(graph: Graph, name: str) -> None:
    type_name, fields = _request_fields(graph, name)
    print(f"Node: {', '.join(service.servers(graph, absolute_name(name)))}")
    print(f"Type: {type_name}")
    print(f"Args: {' '.join(fields)}")


def rosparam_parser() -> argparse.ArgumentParser:
    parser, sub, common = _parser("rosparam", "ROS 1's rosparam, on ROS 2 (ros2 param)")
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
    _no_meaning("rosparam", sub)
    return parser


def rosnode_parser() -> argparse.ArgumentParser:
    parser, sub, common = _parser("rosnode", "ROS 1's rosnode, on ROS 2 (ros2 node)")

    p = sub.add_parser("list", parents=[common], help="list nodes")
    p.set_defaults(run=lambda graph, a: node.list_nodes(graph))

    p = sub.add_parser("info", parents=[common], help="what a node offers")
    p.add_argument("node")
    p.set_defaults(run=lambda graph, a: node.info(graph, a.node))
    _no_meaning("rosnode", sub)
    return parser


def _interface_parser(tool: str, kind: str) -> argparse.ArgumentParser:
    what = interface.KIND_NAMES[kind]
    parser, sub, _common = _parser(tool, f"ROS 1's {tool}, on ROS 2 (ros2 interface)")

    show = sub.add_parser("show", help=f"a {what}")
    show.add_argument("type", nargs="?", help="pkg/Name, Name, or - to read it from stdin")
    show.set_defaults(offline=True, run=lambda _, a: _show(_type_or_stdin(a.type, show), kind))

    p = sub.add_parser("list", help=f"all {what} types")
    p.set_defaults(offline=True, run=lambda _, a: print(*interface.list_types((kind,)), sep="\n"))

    p = sub.add_parser("package", help=f"the {what} types of a package")
    p.add_argument("package")
    p.set_defaults(
        offline=True, run=lambda _, a: print(*interface.list_types((kind,), a.package), sep="\n")
    )

    p = sub.add_parser("packages", help=f"packages with {what} types")
    p.set_defaults(offline=True, run=lambda _, a: print(*interface.packages((kind,)), sep="\n"))
    _no_meaning(tool, sub)
    return parser


def _type_or_stdin(type_name: str | None, parser: argparse.ArgumentParser) -> str:
    """No type given: read it from a pipe (`rosservice type /srv | rossrv show`), as ROS 1
    did; from a terminal that would only sit and wait, so say what is missing instead."""
    if type_name is not None:
        return type_name
    if sys.stdin.isatty():
        parser.error("the following arguments are required: type (or - to read it from stdin)")
    return "-"


def _show(type_name: str, kind: str) -> None:
    type_name = interface.type_name_argument(type_name)
    if type_name.count("/") == 1:  # ROS 1's pkg/Name: this tool says which kind
        package, base = type_name.split("/")
        type_name = f"{package}/{kind}/{base}"
    interface.show(type_name, ros1_style=True, kinds=(kind,))


def _run(parser: argparse.ArgumentParser, argv: Sequence[str] | None) -> int:
    # ROS 1 put options anywhere: `rostopic pub /cmd_vel -r 10 geometry_msgs/Twist '...'`.
    # argparse can parse that only below the command (not through subparsers), so pick it.
    argv = sys.argv[1:] if argv is None else list(argv)
    commands = parser.get_default("commands")
    if argv and argv[0] in commands:
        args = commands[argv[0]].parse_intermixed_args(argv[1:])
    else:
        args = parser.parse_args(argv)  # help, or a usage error
    return run_parsed(args)


@exits_130_on_ctrl_c  # the console script's entry
def rostopic(argv: Sequence[str] | None = None) -> int:
    return _run(rostopic_parser(), argv)


@exits_130_on_ctrl_c
def rosservice(argv: Sequence[str] | None = None) -> int:
    return _run(rosservice_parser(), argv)


@exits_130_on_ctrl_c
def rosparam(argv: Sequence[str] | None = None) -> int:
    return _run(rosparam_parser(), argv)


@exits_130_on_ctrl_c
def rosnode(argv: Sequence[str] | None = None) -> int:
    return _run(rosnode_parser(), argv)


@exits_130_on_ctrl_c
def rosmsg(argv: Sequence[str] | None = None) -> int:
    return _run(_interface_parser("rosmsg", "msg"), argv)


@exits_130_on_ctrl_c
def rossrv(argv: Sequence[str] | None = None) -> int:
    return _run(_interface_parser("rossrv", "srv"), argv)
