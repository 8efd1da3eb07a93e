"""`ros2 param dump NODE`: the node's parameters as a params file, on stdout (`> file.yaml`
saves it)."""

from __future__ import annotations

import argparse
import os
import sys
from typing import Any

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph
from ros2cmd.param.api import add_node_argument, full_node_name, get_values, names

HELP = "Show all of the parameters of a node in a YAML file format"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_node_argument(parser)
    parser.add_argument("--output-dir", help="DEPRECATED: where to save NODE.yaml; use > FILE")


def main(graph: Graph, args: argparse.Namespace) -> None:
    """--output-dir is Humble's deprecated spelling (gone in Jazzy): it still writes
    DIR/NODE.yaml, with Humble's warning."""
    node, output_dir = args.node_name, args.output_dir
    if output_dir is not None and output_dir != "." and not os.path.isdir(output_dir):
        raise ToolError(f"'{output_dir}' is not a valid directory.")
    text = _dump_text(graph, node)
    graph.finish()
    if output_dir is None or output_dir == ".":
        print(text)  # ros2 prints the YAML and a newline: one blank line at the end
        return
    print(
        "WARNING: '--output-dir' is deprecated; use redirection to save to a file",
        file=sys.stderr,
    )
    path = os.path.join(output_dir, full_node_name(node)[1:].replace("/", "__") + ".yaml")
    print("Saving to: ", path)
    try:
        with open(path, "w", encoding="utf-8") as file:
            file.write(text)
    except OSError as error:
        raise ToolError(f"cannot write {path}: {error.strerror}") from None


def _dump_text(graph: Graph, node: str) -> str:
    """/node: / ros__parameters:, the names sorted, nested at each '.'
    (qos_overrides./parameter_events.publisher.depth)."""
    import yaml
    from rclpy.parameter import PARAMETER_SEPARATOR_STRING

    node = full_node_name(node)
    values = get_values(graph, node, names(graph, node))
    tree: dict[str, Any] = {}
    for name, (_, value) in values.items():
        *parents, leaf = name.split(PARAMETER_SEPARATOR_STRING)
        branch = tree
        for part in parents:
            branch = branch.setdefault(part, {})
        branch[leaf] = value
    return yaml.safe_dump({node: {"ros__parameters": tree}}, default_flow_style=False)
