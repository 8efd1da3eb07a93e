"""`ros2 action ...`: list actions and send a goal, showing feedback (like `ros2 action`)."""

from __future__ import annotations

import argparse
import signal
import sys
from typing import Any

from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient

from ros2cmd.action_goal import CtrlC, cancel_goal
from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, absolute_name, add_list_and_type, print_names
from ros2cmd.messages import fill_message, message_to_yaml, parse_yaml
from ros2cmd.typenames import load_type
from ros2cmd.wait import Interrupted, ServerLost, spin_until

STATUS_NAMES = {
    GoalStatus.STATUS_SUCCEEDED: "SUCCEEDED",
    GoalStatus.STATUS_CANCELED: "CANCELED",
    GoalStatus.STATUS_ABORTED: "ABORTED",
}


def _indented(msg: Any) -> str:
    return "\n".join("    " + line for line in message_to_yaml(msg).splitlines())


def action_types(graph: Graph) -> dict[str, list[str]]:
    return graph.action_types()


def list_actions(graph: Graph, show_types: bool = False) -> None:
    print_names(graph, lambda: action_types(graph), show_types)


def print_type(graph: Graph, action: str) -> None:
    action = absolute_name(action)
    types = graph.wait_for(
        lambda: action_types(graph).get(action), f"unknown action '{action}': no server seen"
    )
    print(types[0])


class _Say:
    """How send_goal's cancel reports, in the tool's plain style (see action_goal.cancel_goal)."""

    def info(self, message: str) -> None:
        print(message, flush=True)

    def warning(self, message: str) -> None:
        print(f"warning: {message}", file=sys.stderr, flush=True)

    def error(self, message: str) -> None:
        print(f"error: {message}", file=sys.stderr, flush=True)


def send_goal(
    graph: Graph, action: str, type_name: str, values: Any, feedback: bool = False
) -> None:
    """Send one goal, print feedback if asked, wait for the result however long it takes.

    Ctrl-C cancels the goal on the server (waiting a bounded time for it to confirm), then
    raises Interrupted (exit status 130). A server that goes away is a ToolError.
    """
    action = absolute_name(action)
    action_type = load_type(type_name, ("action",))
    goal = fill_message(action_type.Goal(), values)
    client = ActionClient(graph.node, action_type, action)

    def on_feedback(message: Any) -> None:
        print(f"Feedback:\n{_indented(message.feedback)}\n", flush=True)

    # While the goal is ours, Ctrl-C only sets a flag: ROS must keep running to cancel it.
    ctrl_c = CtrlC()
    previous_handler = signal.signal(signal.SIGINT, ctrl_c)
    interrupted = ctrl_c.is_pressed
    sent = result = None
    try:
        print("Waiting for an action server to become available...", flush=True)
        if not spin_until(
            graph.executor, client.server_is_ready, graph.timeout, interrupted=interrupted
        ):
            raise ToolError(f"no action server for '{action}' (waited {graph.timeout:g} s)")
        print(f"Sending goal:\n{_indented(goal)}\n", flush=True)
        sent = client.send_goal_async(goal, feedback_callback=on_feedback if feedback else None)
        # From now on the server must stay (client=): one that crashed would never answer.
        if not spin_until(
            graph.executor, sent.done, graph.timeout, client=client, interrupted=interrupted
        ):
            raise ToolError(f"no answer to the goal from '{action}' (waited {graph.timeout:g} s)")
        goal_handle = sent.result()
        if not goal_handle.accepted:
            raise ToolError(f"goal rejected by the server of '{action}'")
        print(f"Goal accepted with ID: {bytes(goal_handle.goal_id.uuid).hex()}\n", flush=True)
        result = goal_handle.get_result_async()
        # A goal may run for long: no timeout; Ctrl-C or a lost server ends the wait.
        spin_until(graph.executor, result.done, client=client, interrupted=interrupted)
    except Interrupted:
        answer = cancel_goal(graph.executor, client, sent, result, _Say())
        if answer is not None:
            _print_result(answer)
        raise
    except ServerLost:
        raise ToolError(
            f"the action server of '{action}' went away before the goal finished"
        ) from None
    finally:
        signal.signal(signal.SIGINT, previous_handler)
    answer = result.result()
    if answer.status == GoalStatus.STATUS_SUCCEEDED:
        graph.finish()
    status = _print_result(answer)
    if status != "SUCCEEDED":
        raise ToolError(f"goal finished with status {status}")


def _print_result(answer: Any) -> str:
    """Print a GetResult response as `ros2 action send_goal` does; return the status name."""
    print(f"Result:\n{_indented(answer.result)}\n")
    status = STATUS_NAMES.get(answer.status, str(answer.status))
    print(f"Goal finished with status: {status}", flush=True)
    return status


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("action", help="actions: list, type, send_goal")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    add_list_and_type(sub, common, "action", list_actions, print_type)

    p = sub.add_parser("send_goal", parents=[common], help="send a goal given as YAML")
    p.add_argument("action")
    p.add_argument("type", help="action type, e.g. ros_tutorials_interfaces/action/Fibonacci")
    p.add_argument("values", help="the goal as YAML, e.g. '{order: 5}'")
    p.add_argument("-f", "--feedback", action="store_true", help="print the feedback")
    p.set_defaults(
        run=lambda graph, a: send_goal(graph, a.action, a.type, parse_yaml(a.values), a.feedback)
    )
