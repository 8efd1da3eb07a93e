"""`ros2 param set NODE NAME VALUE`: the node's answer in ros2's words; a refusal is exit
status 1."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from ros2cmd import completion
from ros2cmd.errors import ToolError, ToolFailure
from ros2cmd.graph import Graph
from ros2cmd.param.api import add_node_argument, parameter_value, set_each, with_reason
from ros_tutorials_common.bounded import parameter_problem

if TYPE_CHECKING:
    from rcl_interfaces.msg import ParameterValue

HELP = "Set parameter"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_node_argument(parser)
    parser.add_argument("parameter_name", help="Name of the parameter")
    completion.attach(parser, parameter_name=completion.parameter_names)
    parser.add_argument("value", help="Value of the parameter")


def main(graph: Graph, args: argparse.Namespace) -> None:
    from rcl_interfaces.msg import Parameter as ParameterMsg

    name = args.parameter_name
    value = typed_value(name, args.value)
    node = graph.wait_for_node(args.node_name)
    result = set_each(graph, node, [ParameterMsg(name=name, value=value)])[0]
    if not result.successful:
        raise ToolFailure(with_reason("Setting parameter failed", result))
    graph.finish()
    print(with_reason("Set parameter successful", result))


def typed_value(name: str, text: str) -> ParameterValue:
    """The value `ros2 param set` sends for what was typed: typed as YAML reads it, as
    rclpy's get_parameter_value does (2 an integer, 2.0 a double, true a boolean, a list of
    one of those an array); anything else, a mixed list or a mapping too, is the text itself.
    """
    from ros2cmd.messages import parse_yaml

    try:
        value = parse_yaml(text)
    except ToolError:  # not YAML (`a: b: c`): the text, as rclpy does
        value = text
    for item in value if isinstance(value, list) else [value]:
        if isinstance(item, int) and (problem := parameter_problem(name, item)):
            raise ToolError(f"cannot set {problem}")  # beyond int64: rclpy fails an assert
    kind = _type_name(value)
    return parameter_value(kind, value if kind != "string" or isinstance(value, str) else text)


def _type_name(value: object) -> str:
    """The parameter type a value typed as YAML is sent as (described_type's names)."""
    for kind, scalar in ((bool, "boolean"), (int, "integer"), (float, "double")):
        if isinstance(value, kind):
            return scalar
    if isinstance(value, list):
        for kind, array in (
            (bool, "boolean array"),
            (int, "integer array"),
            (float, "double array"),
            (str, "string array"),
        ):
            # rclpy's tests in its order: [] is a boolean array, [1, true] no integer array
            if all(isinstance(i, kind) and (kind is bool) == isinstance(i, bool) for i in value):
                return array
    return "string"
