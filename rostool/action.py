"""`rostool action ...`: list actions and send a goal, showing feedback (like `ros2 action`)."""

from __future__ import annotations

import argparse
from typing import Any

from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient
from rclpy.action.graph import get_action_names_and_types

from rostool.errors import ToolError
from rostool.graph import Graph, absolute_name
from rostool.messages import fill_message, message_to_yaml, parse_yaml
from rostool.typenames import load_type

STATUS_NAMES = {
    GoalStatus.STATUS_SUCCEEDED: "SUCCEEDED",
    GoalStatus.STATUS_CANCELED: "CANCELED",
    GoalStatus.STATUS_ABORTED: "ABORTED",
}


def _indented(msg: Any) -> str:
    return "\n".join("    " + line for line in message_to_yaml(msg).splitlines())


def action_types(graph: Graph) -> dict[str, list[str]]:
    return dict(get_action_names_and_types(graph.node))


def list_actions(graph: Graph, show_types: bool = False) -> None:
    graph.settle()
    for name, types in sorted(action_types(graph).items()):
        print(f"{name} [{', '.join(types)}]" if show_types else name)


def print_type(graph: Graph, action: str) -> None:
    action = absolute_name(action)
    types = graph.wait_for(
        lambda: action_types(graph).get(action), f"unknown action '{action}': no server seen"
    )
    print(types[0])


def send_goal(
    graph: Graph, action: str, type_name: str, values: Any, feedback: bool = False
) -> None:
    """Send one goal, print feedback if asked, wait for the result however long it takes."""
    action = absolute_name(action)
    action_type = load_type(type_name, ("action",))
    goal = fill_message(action_type.Goal(), values)
    client = ActionClient(graph.node, action_type, action)
    print("Waiting for an action server to become available...", flush=True)
    graph.wait_for(client.server_is_ready, f"no action server for '{action}'")
    print(f"Sending goal:\n{_indented(goal)}\n", flush=True)

    def on_feedback(message: Any) -> None:
        print(f"Feedback:\n{_indented(message.feedback)}\n", flush=True)

    sent = client.send_goal_async(goal, feedback_callback=on_feedback if feedback else None)
    graph.wait_for(sent.done, f"no answer to the goal from '{action}'")
    goal_handle = sent.result()
    if not goal_handle.accepted:
        raise ToolError(f"goal rejected by the server of '{action}'")
    print(f"Goal accepted with ID: {bytes(goal_handle.goal_id.uuid).hex()}\n", flush=True)
    result = goal_handle.get_result_async()
    while not result.done():  # a goal may run for long: no timeout, Ctrl-C ends the wait
        graph.spin_once(0.1)
    answer = result.result()
    print(f"Result:\n{_indented(answer.result)}\n")
    status = STATUS_NAMES.get(answer.status, str(answer.status))
    print(f"Goal finished with status: {status}", flush=True)
    if answer.status != GoalStatus.STATUS_SUCCEEDED:
        raise ToolError(f"goal finished with status {status}")


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("action", help="actions: list, type, send_goal")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    p = sub.add_parser("list", parents=[common], help="list the actions in the graph")
    p.add_argument("-t", "--show-types", action="store_true", help="show each action's type")
    p.set_defaults(run=lambda graph, a: list_actions(graph, a.show_types))

    p = sub.add_parser("type", parents=[common], help="print the type of an action")
    p.add_argument("action")
    p.set_defaults(run=lambda graph, a: print_type(graph, a.action))

    p = sub.add_parser("send_goal", parents=[common], help="send a goal given as YAML")
    p.add_argument("action")
    p.add_argument("type", help="action type, e.g. ros_tutorials_interfaces/action/Fibonacci")
    p.add_argument("values", help="the goal as YAML, e.g. '{order: 5}'")
    p.add_argument("-f", "--feedback", action="store_true", help="print the feedback")
    p.set_defaults(
        run=lambda graph, a: send_goal(graph, a.action, a.type, parse_yaml(a.values), a.feedback)
    )
