"""Plumbing shared by every tutorial node: DDS defaults and the node main loop."""

from ros_tutorials_common.dds import apply_dds_defaults
from ros_tutorials_common.node_main import init, run_node, user_args

__all__ = ["apply_dds_defaults", "init", "run_node", "user_args"]
