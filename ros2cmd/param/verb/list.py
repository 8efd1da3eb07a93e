"""`ros2 param list [NODE]`: every node's name then its parameters, or only NODE's parameters
(no heading), each indented by two spaces."""

from __future__ import annotations

import argparse
import re

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, split_node_name
from ros2cmd.param.api import (
    add_node_argument,
    ask,
    described_type,
    names,
    names_of_each,
    nodes_with_parameters,
    silent_nodes_error,
)

HELP = "Output a list of available parameters"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_node_argument(parser, nargs="?")
    parser.add_argument(
        "--filter",
        metavar="REGEX",
        help="Only parameters matching the regex expression will be showed. "
        "Supports `re` regex syntax.",
    )
    parser.add_argument(
        "--param-prefixes",
        nargs="+",
        default=[],
        help="Only list parameters with the provided prefixes",
    )
    parser.add_argument(
        "--param-type", action="store_true", help="Print parameter types with parameter names"
    )


def main(graph: Graph, args: argparse.Namespace) -> None:
    node, prefixes, with_types = args.node_name, args.param_prefixes, args.param_type
    try:
        regex = re.compile(args.filter) if args.filter is not None else None
    except re.error as error:
        raise ToolError(f"invalid --filter regular expression {args.filter!r}: {error}") from None
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
            descriptors = ask(
                graph, full_name, lambda client, f=found: client.describe_parameters(f)
            )
            types = {d.name: described_type(d.type) for d in descriptors.descriptors}
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


def _listing_order(full_name: str) -> tuple[str, str, str]:
    # ros2param sorts its NodeName tuples: by the node's own name, then its namespace.
    namespace, name = split_node_name(full_name)
    return name, namespace, full_name
