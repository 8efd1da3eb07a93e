"""`rosnode list|info`: ROS 1's rosnode on `ros2 node`'s code."""

from __future__ import annotations

import argparse
from collections.abc import Sequence

from ros2cmd import completion, node
from ros2cmd.daemon.client import about_node
from ros2cmd.ros1 import tool
from ros_tutorials_common.shutdown import program_main


def rosnode_parser() -> argparse.ArgumentParser:
    parser, sub, common = tool.new_parser("rosnode", "ROS 1's rosnode, on ROS 2 (ros2 node)")

    p = sub.add_parser("list", parents=[common], help="list nodes")
    p.set_defaults(daemon=True, run=lambda graph, a: node.list_nodes(graph))

    p = sub.add_parser("info", parents=[common], help="what a node offers")
    p.add_argument("node")
    completion.attach(p, node=completion.node_names)
    p.set_defaults(
        daemon=lambda a: about_node(a.node),
        run=lambda graph, a: node.info(graph, a.node),
    )
    tool.no_ros2_meaning("rosnode", sub)
    return parser


@program_main  # the console script's entry
def rosnode(argv: Sequence[str] | None = None) -> int:
    return tool.run(rosnode_parser(), argv)
