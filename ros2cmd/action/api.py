"""What the `ros2 action` sub-verbs share: goal status names, the types servers offer."""

from __future__ import annotations

from ros2cmd.graph import Graph


def status_name(status: int) -> str:
    """A goal status as ros2action prints it (action_msgs/msg/GoalStatus)."""
    from action_msgs.msg import GoalStatus

    names = {
        GoalStatus.STATUS_ACCEPTED: "ACCEPTED",
        GoalStatus.STATUS_EXECUTING: "EXECUTING",
        GoalStatus.STATUS_CANCELING: "CANCELING",
        GoalStatus.STATUS_SUCCEEDED: "SUCCEEDED",
        GoalStatus.STATUS_CANCELED: "CANCELED",
        GoalStatus.STATUS_ABORTED: "ABORTED",
    }
    return names.get(status, "UNKNOWN")


def server_types(graph: Graph, action: str) -> list[str]:
    """The types the action's servers offer (of other nodes than ours, whose client has the
    type asked for)."""
    node = graph.node
    types: set[str] = set()
    for name, namespace in node.get_node_names_and_namespaces():
        if (name, namespace) == (node.get_name(), node.get_namespace()):
            continue
        for server, server_types in graph.node_actions(name, namespace)[0]:
            if server == action:
                types.update(server_types)
    return sorted(types)
