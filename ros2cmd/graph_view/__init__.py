"""`rqt_graph` (also `ros2 run rqt_graph rqt_graph`): the running graph as rqt_graph draws it.

Nodes are boxes, topics ellipses, an arrow from each publisher to its topic and from the
topic to each subscriber; nodes and topics of one namespace are grouped in a labelled frame.
As rqt_graph does by default, the tools' own nodes, /rosout and /parameter_events are left
out (``--all`` shows the last two). Services are not drawn (rqt_graph does not either: a call
is not a lasting connection).

    rqt_graph                      DOT on stdout (for graphviz, if you have it)
    rqt_graph -o graph.svg         an SVG picture (or .png, or .dot)
    rqt_graph --window             a window that follows nodes as they come and go
    rqt_graph                          the window where there is a display, else DOT

This module is the command (its options, what it writes where); model.py takes the picture
from the graph, window.py is the window; the drawing itself (the model, where each thing goes,
the DOT, SVG and PNG output) is ros_tutorials_common/drawing/, which view_frames draws with too.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, until_stopped
from ros2cmd.graph_view.model import current_model
from ros2cmd.graph_view.window import window as show_window  # the module keeps its name
from ros_tutorials_common.drawing.model import GraphModel
from ros_tutorials_common.drawing.render import CannotWrite, to_dot, write


def run(graph: Graph, args: argparse.Namespace) -> None:
    groups, all_topics = not args.no_groups, args.all
    if args.window:
        with until_stopped():  # Ctrl-C is how a window that follows the graph ends: exit 0
            show_window(graph, groups, all_topics)
        return
    graph.settle()
    model = current_model(graph, groups, all_topics)
    if args.output:
        try:
            write(model, Path(args.output))
        except CannotWrite as error:
            raise ToolError(str(error)) from None
        print(f"wrote {args.output}: {_counts(model)}", file=sys.stderr)
    else:
        sys.stdout.write(to_dot(model))


def _counts(model: GraphModel) -> str:
    kinds = [v.kind for v in model.vertices.values()]
    nodes, topics = kinds.count("node"), kinds.count("topic")
    return f"{nodes} node(s), {topics} topic(s), {len(model.edges)} edge(s)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-o", "--output", help="write a .svg, .png or .dot file")
    parser.add_argument(
        "--window", action="store_true", help="show it in a window that follows the graph"
    )
    parser.add_argument("--no-groups", action="store_true", help="do not frame namespaces")
    parser.add_argument("--all", action="store_true", help="show /rosout and /parameter_events too")
