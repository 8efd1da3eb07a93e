"""`ros2 param get NODE NAME [--hide-type]`: `Integer value is: 86`."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.graph import Graph
from ros2cmd.param.api import add_node_argument, get_values

HELP = "Get parameter"


def get_label(param_type: int) -> str:
    """How `ros2 param get` introduces a value of each type."""
    from rcl_interfaces.msg import ParameterType

    labels = {
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
    return labels.get(param_type, f"Unknown parameter type '{param_type}'")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_node_argument(parser)
    parser.add_argument("parameter_name", help="Name of the parameter")
    completion.attach(parser, parameter_name=completion.parameter_names)
    parser.add_argument("--hide-type", action="store_true", help="Hide the type information")


def main(graph: Graph, args: argparse.Namespace) -> None:
    name = args.parameter_name
    param_type, value = get_values(graph, args.node_name, [name])[name]
    graph.finish()
    if args.hide_type:
        print(value)
    else:
        print(get_label(param_type), value)
