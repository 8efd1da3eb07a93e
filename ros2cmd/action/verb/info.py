"""`ros2 action info ACTION`: its clients and servers."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.graph import Graph, ServiceInfo, absolute_name

HELP = "Print information about an action"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "action_name", help="Name of the ROS action to get info (e.g. '/fibonacci')"
    )
    completion.attach(parser, action_name=completion.action_names)
    parser.add_argument(
        "-t", "--show-types", action="store_true", help="Additionally show the action type"
    )
    parser.add_argument(
        "-c",
        "--count",
        action="store_true",
        help="Only display the number of action clients and action servers",
    )


def main(graph: Graph, args: argparse.Namespace) -> None:
    info(graph, args.action_name, args.show_types, args.count)


def info(graph: Graph, action: str, show_types: bool = False, count: bool = False) -> None:
    """`ros2 action info ACTION`: its clients and servers (node names), once discovery of
    what was running has settled."""
    action = absolute_name(action)
    graph.settle()
    entry: ServiceInfo = graph.wait_for(
        lambda: graph.snapshot().actions.get(action),
        f"unknown action '{action}': no server or client seen",
    )
    graph.finish()
    print(f"Action: {action}")
    for title, nodes in (("Action clients", entry.clients), ("Action servers", entry.servers)):
        print(f"{title}: {len(nodes)}")
        if not count:
            for node in nodes:
                print(f"    {node} [{', '.join(entry.types)}]" if show_types else f"    {node}")
