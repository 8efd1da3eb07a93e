"""The ROS 1 spellings: rostopic, rosservice, rosparam, rosnode, rosmsg, rossrv.

The seeds' commands work as printed (``rosservice call /ros_tutorial_srv 10 5``,
``rosparam set /calculation_method 2``) and run the same code as ``rostool``. Two ROS 1
habits need translating:

- Values by position: ``rosservice call /srv 10 5`` fills the request's fields in order.
- One global parameter server: ROS 2 has none, every parameter belongs to a node. A ROS 1
  name is looked up: ``/service_server/calculation_method`` names the node; a bare
  ``/calculation_method`` is found on whichever node declares it (if several do, the
  command says so and asks for the node).

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

from ros_tutorials_common.cli import positive_int, positive_rate
from rostool import interface, node, param, service, topic
from rostool.cli import common_options, run_parsed
from rostool.errors import ToolError
from rostool.graph import Graph, absolute_name
from rostool.messages import parse_yaml
from rostool.typenames import load_type

# ROS 1 commands that have no ROS 2 counterpart, and what to do instead.
NO_ROS2_MEANING = {
    ("rosnode", "kill"): "ROS 2 has no master to kill nodes through; stop the node's process "
    "(Ctrl-C in its terminal or the launcher's, or `kill PID`)",
    ("rosnode", "ping"): "ROS 2 nodes have no XML-RPC address to ping; `rosnode info NODE` "
    "shows whether the node is in the graph",
    ("rosnode", "machine"): "ROS 2 does not record which machine a node runs on; "
    "`rosnode list` (or `rostool node list`) shows every node in the graph",
    ("rosnode", "cleanup"): "ROS 2 has no master registry to clean; DDS drops vanished nodes "
    "by itself, and `rosnode list` shows the ones still there",
    ("rosservice", "uri"): "ROS 2 services have no ROSRPC URI (they travel over DDS); "
    "`rosservice info SERVICE` shows the node that serves it and its type",
    ("rosparam", "delete"): "a ROS 2 parameter belongs to its node and stays declared; set "
    "another value with `rosparam set`",
    ("rosmsg", "md5"): "ROS 2 types have no MD5 sum; `rosmsg show` gives the definition",
    ("rossrv", "md5"): "ROS 2 types have no MD5 sum; `rossrv show` gives the definition",
    ("rosmsg", "users"): "ROS 2 keeps no index of the code that uses a type; "
    "`rostopic find TYPE` (or `rostool topic find TYPE`) lists the topics that carry it",
    ("rossrv", "users"): "ROS 2 keeps no index of the code that uses a type; "
    "`rosservice find TYPE` (or `rostool service find TYPE`) lists the services that use it",
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


# rosparam: ROS 1 names onto (node, parameter).


def resolve_parameter(graph: Graph, name: str) -> tuple[str, str]:
    """'/calculation_method' -> ('/service_server', 'calculation_method'), waiting for it."""
    name = "/" + name.strip("/")
    known: dict[str, list[str]] = {}

    def find() -> list[tuple[str, str]]:
        nodes = param.nodes_with_parameters(graph)
        for node_name in sorted(nodes, key=len, reverse=True):
            if name.startswith(node_name + "/"):  # the name says which node
                return [(node_name, name[len(node_name) + 1 :])]
        for node_name in nodes:
            if node_name not in known:
                known[node_name] = param.names(graph, node_name)
        return [(n, name[1:]) for n in nodes if name[1:] in known[n]]

    matches = graph.wait_for(find, f"no node declares a parameter '{name[1:]}'")
    if len(matches) > 1:
        holders = ", ".join(node_name for node_name, _ in matches)
        raise ToolError(
            f"parameter '{name[1:]}' is declared by several nodes ({holders}); "
            f"name one, e.g. {matches[0][0]}/{name[1:]}"
        )
    return matches[0]


def _value_text(value: Any) -> str:
    if isinstance(value, (list, dict)):
        return yaml.safe_dump(value, default_flow_style=True).strip()
    return str(value).lower() if isinstance(value, bool) else str(value)


def rosparam_list(graph: Graph) -> None:
    for node_name in param.nodes_with_parameters(graph):
        for name in param.names(graph, node_name):
            print(f"{node_name}/{name}")


def rosparam_get(graph: Graph, name: str) -> None:
    node_name, param_name = resolve_parameter(graph, name)
    _, value = param.get_values(graph, node_name, [param_name])[param_name]
    print(_value_text(value))


def rosparam_set(graph: Graph, name: str, value: str) -> None:
    node_name, param_name = resolve_parameter(graph, name)
    param.set_values(graph, node_name, {param_name: parse_yaml(value)})


def rosparam_dump(graph: Graph, path: str | None) -> None:
    data: dict[str, Any] = {}
    for node_name in param.nodes_with_parameters(graph):
        data.update(param.dump_data(graph, node_name))
    text = yaml.safe_dump(data, default_flow_style=False)
    if path:
        try:
            Path(path).write_text(text)
        except OSError as error:
            raise ToolError(f"cannot write {path}: {error.strerror}") from None
    else:
        print(text.rstrip())


def rosparam_load(graph: Graph, path: str) -> None:
    data = param.read_params_file(path)  # read and checked once, before touching any node
    if any(not str(key).startswith("/") for key in data):
        raise ToolError(f"{path}: expected '/node_name: ros__parameters: ...' entries")
    if "/**" in data:
        raise ToolError(f"{path} is for any node ('/**'); use: rostool param load NODE FILE")
    for node_name in data:
        param.load_values(graph, node_name, param.params_for_node(data, path, node_name))


# The tools. Each is a parser whose commands call the rostool functions.


def _parser(tool: str, description: str) -> tuple[argparse.ArgumentParser, Any, Any]:
    parser = argparse.ArgumentParser(prog=tool, description=description)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    parser.set_defaults(commands=sub.choices)  # for _run
    return parser, sub, common_options()


def _add(sub: Any, common: Any, name: str, run: Callable, help: str, offline: bool = False) -> Any:
    p = sub.add_parser(name, parents=[] if offline else [common], help=help)
    p.set_defaults(run=run, offline=offline)
    return p


def _no_meaning(tool: str, sub: Any) -> None:
    for (owner, command), reason in NO_ROS2_MEANING.items():
        if owner == tool:
            p = sub.add_parser(command, help="(no ROS 2 counterpart)")
            p.add_argument("rest", nargs="*")
            p.set_defaults(run=_refuse(f"{tool} {command}", reason), offline=True)


def _refuse(command: str, reason: str) -> Callable:
    def run(_graph: Graph | None, _args: argparse.Namespace) -> None:
        raise ToolError(f"`{command}` has no ROS 2 meaning: {reason}")

    return run


def rostopic_parser() -> argparse.ArgumentParser:
    parser, sub, common = _parser("rostopic", "ROS 1's rostopic, on ROS 2 (see: rostool topic)")
    _add(sub, common, "list", lambda g, a: topic.list_topics(g, a.verbose), "list topics")
    sub.choices["list"].add_argument("-v", "--verbose", action="store_true", help="with types")
    p = _add(sub, common, "echo", lambda g, a: topic.echo(g, a.topic, count=a.n), "print messages")
    p.add_argument("topic")
    p.add_argument("-n", type=positive_int, help="print this many messages, then exit")
    p = _add(sub, common, "pub", lambda g, a: _pub(g, a), "publish a message")
    p.add_argument("topic")
    p.add_argument("type")
    p.add_argument("values", nargs="*", help="a YAML mapping, or field values in order")
    group = p.add_mutually_exclusive_group()  # ROS 1 refused both too
    group.add_argument("-r", "--rate", type=positive_rate, help="publish at this rate until Ctrl-C")
    group.add_argument("-1", "--once", action="store_true", help="publish once, then exit")
    for name, bandwidth in (("hz", False), ("bw", True)):
        p = _add(sub, common, name, lambda g, a, b=bandwidth: topic.hz(g, a.topic, 10000, b), "")
        p.add_argument("topic")
    p = _add(sub, common, "info", lambda g, a: topic.info(g, a.topic, True), "publishers etc.")
    p.add_argument("topic")
    p = _add(sub, common, "type", lambda g, a: topic.print_type(g, a.topic), "message type")
    p.add_argument("topic")
    p = _add(sub, common, "find", lambda g, a: topic.find(g, a.type), "topics of a type")
    p.add_argument("type")
    return parser


def _pub(graph: Graph, args: argparse.Namespace) -> None:
    values = values_from_args(args.values)
    if args.rate is not None:
        topic.pub(graph, args.topic, args.type, values, rate=args.rate)
    elif args.once:
        topic.pub(graph, args.topic, args.type, values, times=1)
    else:  # ROS 1's default: publish once, latched, until Ctrl-C
        topic.pub(graph, args.topic, args.type, values, rate=None, latch=True)


def rosservice_parser() -> argparse.ArgumentParser:
    parser, sub, common = _parser("rosservice", "ROS 1's rosservice, on ROS 2 (rostool service)")
    _add(sub, common, "list", lambda g, a: service.list_services(g), "list services")
    p = _add(sub, common, "type", lambda g, a: service.print_type(g, a.service), "service type")
    p.add_argument("service")
    p = _add(sub, common, "call", lambda g, a: _call(g, a), "call a service")
    p.add_argument("service")
    p.add_argument("values", nargs="*", help="a YAML mapping, or field values in order")
    p = _add(sub, common, "args", lambda g, a: _service_args(g, a.service), "request fields")
    p.add_argument("service")
    p = _add(sub, common, "info", lambda g, a: _service_info(g, a.service), "node, type, args")
    p.add_argument("service")
    p = _add(sub, common, "find", lambda g, a: service.find(g, a.type), "services of a type")
    p.add_argument("type")
    _no_meaning("rosservice", sub)
    return parser


def _call(graph: Graph, args: argparse.Namespace) -> None:
    values = values_from_args(args.values)
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
    parser, sub, common = _parser("rosparam", "ROS 1's rosparam, on ROS 2 (rostool param)")
    _add(sub, common, "list", lambda g, a: rosparam_list(g), "list /node/parameter names")
    p = _add(sub, common, "get", lambda g, a: rosparam_get(g, a.name), "print a value")
    p.add_argument("name", help="/node/parameter, or /parameter if one node declares it")
    p = _add(sub, common, "set", lambda g, a: rosparam_set(g, a.name, a.value), "set a value")
    p.add_argument("name", help="/node/parameter, or /parameter if one node declares it")
    p.add_argument("value", help="a YAML value: 2, 2.5, true, text")
    p = _add(sub, common, "dump", lambda g, a: rosparam_dump(g, a.file), "all parameters")
    p.add_argument("file", nargs="?", help="write here instead of printing")
    p = _add(sub, common, "load", lambda g, a: rosparam_load(g, a.file), "set from a dump")
    p.add_argument("file")
    _no_meaning("rosparam", sub)
    return parser


def rosnode_parser() -> argparse.ArgumentParser:
    parser, sub, common = _parser("rosnode", "ROS 1's rosnode, on ROS 2 (rostool node)")
    _add(sub, common, "list", lambda g, a: node.list_nodes(g), "list nodes")
    p = _add(sub, common, "info", lambda g, a: node.info(g, a.node), "what a node offers")
    p.add_argument("node")
    _no_meaning("rosnode", sub)
    return parser


def _interface_parser(tool: str, kind: str) -> argparse.ArgumentParser:
    what = interface.KIND_NAMES[kind]
    parser, sub, common = _parser(tool, f"ROS 1's {tool}, on ROS 2 (rostool interface)")
    show = _add(
        sub,
        common,
        "show",
        lambda g, a: _show(_type_or_stdin(a.type, show), kind),
        f"a {what}",
        offline=True,
    )
    show.add_argument("type", nargs="?", help="pkg/Name, Name, or - to read it from stdin")
    _add(
        sub,
        common,
        "list",
        lambda g, a: print(*interface.list_types((kind,)), sep="\n"),
        f"all {what} types",
        offline=True,
    )
    p = _add(
        sub,
        common,
        "package",
        lambda g, a: print(*interface.list_types((kind,), a.package), sep="\n"),
        f"the {what} types of a package",
        offline=True,
    )
    p.add_argument("package")
    _add(
        sub,
        common,
        "packages",
        lambda g, a: print(*interface.packages((kind,)), sep="\n"),
        f"packages with {what} types",
        offline=True,
    )
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


def rostopic(argv: Sequence[str] | None = None) -> int:
    return _run(rostopic_parser(), argv)


def rosservice(argv: Sequence[str] | None = None) -> int:
    return _run(rosservice_parser(), argv)


def rosparam(argv: Sequence[str] | None = None) -> int:
    return _run(rosparam_parser(), argv)


def rosnode(argv: Sequence[str] | None = None) -> int:
    return _run(rosnode_parser(), argv)


def rosmsg(argv: Sequence[str] | None = None) -> int:
    return _run(_interface_parser("rosmsg", "msg"), argv)


def rossrv(argv: Sequence[str] | None = None) -> int:
    return _run(_interface_parser("rossrv", "srv"), argv)
