"""ROS names as rcl takes them in a remap rule: one check for the launcher and rosrun.

Parts of letters, digits and _ (not starting with a digit) separated by single /, relative,
absolute (/a) or private (~/a); a rule's "from" may start with rostopic:// or rosservice://.
No spaces, no {node}, no wildcards, no trailing /, no bare ~ (rcl refuses them all).
"""

from __future__ import annotations

import re

TOKEN = r"[A-Za-z_][A-Za-z0-9_]*"  # one part of a node, namespace, topic or parameter name
RULE = "letters, digits and underscores, not starting with a digit"
_REMAP_NAME = re.compile(rf"(~/|/)?{TOKEN}(/{TOKEN})*")
_FROM_PREFIXES = ("rostopic://", "rosservice://")
# A service's introspection topic is SERVICE + this (rcl's RCL_SERVICE_INTROSPECTION_TOPIC_POSTFIX).
SERVICE_EVENT_SUFFIX = "/_service_event"


def valid_remap_name(name: str, side: str) -> bool:
    """Whether rcl takes ``name`` as the ``side`` ("from" or "to") of a remap rule."""
    if side == "from":
        for prefix in _FROM_PREFIXES:
            if name.startswith(prefix):
                name = name[len(prefix) :]
                break
    return _REMAP_NAME.fullmatch(name) is not None
