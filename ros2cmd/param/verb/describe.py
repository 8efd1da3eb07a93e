"""`ros2 param describe NODE NAME...`: each parameter's type, description and constraints."""

from __future__ import annotations

import argparse
from typing import Any

from ros2cmd import completion
from ros2cmd.graph import Graph
from ros2cmd.param.api import add_node_argument, ask, described_type, get_values

HELP = "Show descriptive information about declared parameters"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_node_argument(parser)
    parser.add_argument("parameter_names", nargs="+", help="Names of the parameters")
    completion.attach(parser, parameter_names=completion.parameter_names)


def main(graph: Graph, args: argparse.Namespace) -> None:
    descriptors = _describe(graph, args.node_name, args.parameter_names)
    graph.finish()
    for descriptor in descriptors:
        print(f"Parameter name: {descriptor.name}")
        print(f"  Type: {described_type(descriptor.type)}")
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


def _describe(graph: Graph, node: str, params: list[str]) -> list[Any]:
    """The ParameterDescriptors of a node's parameters; an unknown name is a ToolError."""
    get_values(graph, node, params)  # rclpy describes an unknown name as "not set": refuse it
    return list(ask(graph, node, lambda client: client.describe_parameters(params)).descriptors)
