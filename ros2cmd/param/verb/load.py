"""`ros2 param load NODE FILE`: set what a params file gives a node (see api.py's docstring)."""

from __future__ import annotations

import argparse

from ros2cmd.graph import Graph
from ros2cmd.param.api import ParamsFile, add_node_argument, full_node_name, print_loaded, set_each

HELP = "Load parameter file for a node"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_node_argument(parser)
    parser.add_argument("parameter_file", help="Parameter file")
    parser.add_argument(
        "--no-use-wildcard",
        action="store_true",
        help="Do not load parameters in the '/**' namespace into the node",
    )


def main(graph: Graph, args: argparse.Namespace) -> None:
    node = args.node_name
    params = ParamsFile(args.parameter_file).params_for(
        full_node_name(node), not args.no_use_wildcard
    )
    results = set_each(graph, node, params)
    graph.finish()
    print_loaded(params, results)
