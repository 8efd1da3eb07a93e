"""`ros2 param delete NODE NAME`: set to 'not set', which undeclares it where the node allows."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.errors import ToolFailure
from ros2cmd.graph import Graph
from ros2cmd.param.api import add_node_argument, set_each, with_reason

HELP = "Delete parameter"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_node_argument(parser)
    parser.add_argument("parameter_name", help="Name of the parameter")
    completion.attach(parser, parameter_name=completion.parameter_names)


def main(graph: Graph, args: argparse.Namespace) -> None:
    from rcl_interfaces.msg import Parameter as ParameterMsg
    from rcl_interfaces.msg import ParameterType, ParameterValue

    node = graph.wait_for_node(args.node_name)
    unset = ParameterValue(type=ParameterType.PARAMETER_NOT_SET)
    result = set_each(graph, node, [ParameterMsg(name=args.parameter_name, value=unset)])[0]
    if not result.successful:
        raise ToolFailure(with_reason("Deleting parameter failed", result))
    graph.finish()
    print(with_reason("Deleted parameter successfully", result))
