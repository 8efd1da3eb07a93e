"""TAB completion's names of the running system and of interface types, for ros2's and the ROS 1
tools' arguments (``completion.attach(p, topic_name=completion.topic_names)`` next to each
argument).

The running system's names come from the daemon (`ros2 daemon start`; a list started once
starts it too): one question over its socket, answered at once with what its graph holds
(daemon/client.py, ``ask_names``). No daemon running, or none answering in time: nothing
completes; a completion never starts a daemon nor a DDS participant of its own, and never
loads rclpy. This
module imports what its completers need when they run, so that the verbs that name them load
nothing for it (`ros2 run` starts without the graph module, for one). The machinery, and the
names of the ament index (packages, executables, launch files), are in
ros_tutorials_common/completion.py.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable, Iterable
from functools import cache
from typing import Any

from ros_tutorials_common import completion

Completer = Callable[..., Iterable[str]]
# Named here for the verbs: how an argument says what completes it, and the ament index's names.
attach = completion.attach
answer = completion.answer
requested = completion.requested
package_names = completion.package_names
executable_names = completion.executable_names
MAX_DAEMON_WAIT = 0.1  # s: at most this of the budget goes to the daemon's answer


@cache
def _daemon_names() -> dict[str, Any]:
    """The daemon's answer ({} if there is none to ask, or none came in time)."""
    from ros2cmd.daemon import client as daemon

    if not daemon.use_daemon(no_daemon=False):
        return {}
    return daemon.ask_names(min(MAX_DAEMON_WAIT, completion.remaining())) or {}


def _names(kind: str, parsed_args: argparse.Namespace | None, hidden_option: str = "") -> list[str]:
    from ros2cmd.graph import is_hidden

    names = [entry[0] for entry in _daemon_names().get(kind, [])]
    if not (hidden_option and getattr(parsed_args, hidden_option, False)):
        names = [name for name in names if not is_hidden(name)]
    return sorted(set(names))


def topic_names(parsed_args: argparse.Namespace | None = None, **_: Any) -> list[str]:
    return _names("topics", parsed_args, "include_hidden_topics")


def service_names(parsed_args: argparse.Namespace | None = None, **_: Any) -> list[str]:
    return _names("services", parsed_args, "include_hidden_services")


def action_names(parsed_args: argparse.Namespace | None = None, **_: Any) -> list[str]:
    return _names("actions", parsed_args)


def node_names(parsed_args: argparse.Namespace | None = None, **_: Any) -> list[str]:
    """/ns/name of every node but the hidden ones (unless --include-hidden-nodes)."""
    from ros2cmd.graph import join_node_name

    show_hidden = getattr(parsed_args, "include_hidden_nodes", False)
    found = set()
    for name, namespace in _daemon_names().get("nodes", []):
        if show_hidden or not name.startswith("_"):
            found.add(join_node_name(namespace, name))
    return sorted(found)


def parameter_names(parsed_args: argparse.Namespace | None = None, **_: Any) -> list[str]:
    """The parameters of the node named before (`ros2 param get /turtlesim <TAB>`), which the
    daemon asks it for: the first time for a node may come too late, and complete nothing."""
    from ros2cmd.daemon import client as daemon

    node = getattr(parsed_args, "node_name", None)
    if not node or not daemon.use_daemon(no_daemon=False):
        return []
    return daemon.ask_parameters(node, min(MAX_DAEMON_WAIT, completion.remaining()))


def interface_types(kinds: tuple[str, ...], ros1: bool = False) -> Completer:
    """A completer of the interface types of KINDS ('msg', 'srv', 'action') in the ament index:
    pkg/msg/Name, or as the ROS 1 tools name them, pkg/Name."""

    def complete(**_: Any) -> list[str]:
        from ros2cmd.typenames import interface_index

        found = set()
        for package, names in interface_index().items():
            for name in names:
                kind, _, short = name.partition("/")
                if kind in kinds:
                    found.add(f"{package}/{short}" if ros1 else f"{package}/{name}")
        return sorted(found)

    return complete


def _ros1_name(type_name: str) -> str:
    """geometry_msgs/msg/Twist -> geometry_msgs/Twist."""
    package, _, name = type_name.partition("/")
    return f"{package}/{name.partition('/')[2] or name}"


def interface_packages(**_: Any) -> list[str]:
    """The packages that have interfaces (`ros2 interface package <TAB>`)."""
    from ros2cmd.typenames import interface_index

    return sorted(interface_index())


message_types = interface_types(("msg",))
service_types = interface_types(("srv",))
action_types = interface_types(("action",))
all_types = interface_types(("msg", "srv", "action"))


def types_of(kind: str, name_key: str, every: Completer, ros1: bool = False) -> Completer:
    """A type completer that offers the types the daemon sees on the name given before (`ros2
    topic pub /turtle1/cmd_vel <TAB>`: geometry_msgs/msg/Twist; with ros1, geometry_msgs/Twist),
    else every type of that kind."""

    def complete(parsed_args: argparse.Namespace | None = None, **kwargs: Any) -> list[str]:
        name = getattr(parsed_args, name_key, None)
        if name:
            name = name if name.startswith("/") else f"/{name}"
            for found, types in _daemon_names().get(kind, []):
                if found == name:
                    return sorted(_ros1_name(t) if ros1 else t for t in types)
        return list(every(parsed_args=parsed_args, **kwargs))

    return complete


types_for_topic = types_of("topics", "topic_name", message_types)
types_for_service = types_of("services", "service_name", service_types)
types_for_action = types_of("actions", "action_name", action_types)

# The ROS 1 tools' spelling of types: pkg/Name.
ros1_message_types = interface_types(("msg",), ros1=True)
ros1_service_types = interface_types(("srv",), ros1=True)
ros1_types_for_topic = types_of("topics", "topic", ros1_message_types, ros1=True)
