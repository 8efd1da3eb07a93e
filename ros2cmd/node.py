"""`ros2 node ...`: the nodes in the graph and what each one offers (ROS 2's ros2node).

    ros2 node list [-a] [-c]          one full name a line, sorted; -a with hidden nodes,
                                      -c only how many
    ros2 node info /turtlesim [--include-hidden]

`info` prints ros2node's block: the node's name, then `  Subscribers:`, `  Publishers:`,
`  Service Servers:`, `  Service Clients:`, `  Action Servers:`, `  Action Clients:`, each
followed by its `    /name: pkg/kind/Type` lines, or by an empty line when it has none (as
ros2node prints it). Names with a hidden part (an action's `/_action/feedback` topic and
`/_action/send_goal` service) are left out unless --include-hidden.
"""

from __future__ import annotations

import argparse
import sys

from ros2cmd import completion
from ros2cmd.daemon.client import about_node
from ros2cmd.graph import Graph, is_hidden, join_node_name, split_node_name
from ros2cmd.sub_verbs import VERB_HELP, add_count_option

# What `ros2 node list` and `ros2 node info` print (to stderr) for nodes of one name.
DUPLICATES_WARNING = (
    "WARNING: Be aware that there are nodes in the graph that share an exact name, "
    "which can have unintended side effects."
)
INFO_DUPLICATES_WARNING = (
    'There are {count} nodes in the graph with the exact name "{name}". '
    "You are seeing information about only one of them."
)


def node_names(graph: Graph, include_hidden: bool = False) -> list[str]:
    """Every node's full name, sorted, a name once per node that has it."""
    if not include_hidden:
        return graph.node_names()
    names = graph.node.get_node_names_and_namespaces()
    return sorted(join_node_name(namespace, name) for name, namespace in names)


def list_nodes(graph: Graph, include_hidden: bool = False, count: bool = False) -> None:
    graph.settle()
    names = node_names(graph, include_hidden)
    graph.finish()
    if count:
        print(len(names))
        return
    if len(set(names)) < len(names):
        print(DUPLICATES_WARNING, file=sys.stderr)
    for name in names:
        print(name)


def info(graph: Graph, full_name: str, include_hidden: bool = False) -> None:
    full_name = graph.wait_for_node(full_name)
    namespace, name = split_node_name(full_name)
    graph.settle()  # the node is known; let its endpoints arrive too
    count = node_names(graph, include_hidden=True).count(full_name)
    node = graph.node
    action_servers, action_clients = graph.node_actions(name, namespace)
    sections = {
        "Subscribers": node.get_subscriber_names_and_types_by_node(name, namespace),
        "Publishers": node.get_publisher_names_and_types_by_node(name, namespace),
        "Service Servers": node.get_service_names_and_types_by_node(name, namespace),
        "Service Clients": node.get_client_names_and_types_by_node(name, namespace),
        "Action Servers": action_servers,
        "Action Clients": action_clients,
    }
    graph.finish()
    if count > 1:
        print(INFO_DUPLICATES_WARNING.format(count=count, name=full_name), file=sys.stderr)
    print(full_name)
    for title, endpoints in sections.items():
        print(f"  {title}:")
        shown = [
            f"    {endpoint}: {', '.join(types)}"
            for endpoint, types in sorted(endpoints)
            if include_hidden or not is_hidden(endpoint)
        ]
        print(*shown, sep="\n")  # none: an empty line, as ros2node prints it


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("node", help=VERB_HELP["node"])
    sub = parser.add_subparsers(dest="command", metavar="Commands", required=True)

    p = sub.add_parser("list", parents=[common], help="Output a list of available nodes")
    p.add_argument("-a", "--all", action="store_true", help="Display all nodes even hidden ones")
    add_count_option(p, "nodes")
    p.set_defaults(daemon=True, run=lambda graph, a: list_nodes(graph, a.all, a.count_nodes))

    p = sub.add_parser("info", parents=[common], help="Output information about a node")
    p.add_argument("node_name", help="Node name to request information")
    completion.attach(p, node_name=completion.node_names)
    p.add_argument(
        "--include-hidden",
        action="store_true",
        help="Display hidden topics, services, and actions as well",
    )
    p.set_defaults(
        daemon=lambda a: about_node(a.node_name),
        run=lambda graph, a: info(graph, a.node_name, a.include_hidden),
    )
