"""`ros2 action send_goal ACTION TYPE [GOAL]`, printed as ROS 2 Jazzy's ros2action does.

It prints the goal, its ID, the feedback (with --feedback), the result and the final status in
ros2action's layout; Ctrl-C cancels the goal on the server (`Canceling goal...`, `Goal
canceled.`) and ends with exit status 130. Where ros2action would wait forever (for a server
that never comes), this waits --timeout seconds and says why it stops.
"""

from __future__ import annotations

import argparse
import signal
import sys
import time
from typing import TYPE_CHECKING, Any

from ros2cmd import completion
from ros2cmd.action.api import server_types, status_name
from ros2cmd.action.goal import cancel_goal
from ros2cmd.errors import ToolError, ToolFailure
from ros2cmd.graph import Graph, absolute_name
from ros2cmd.typenames import full_type_name, load_type
from ros_tutorials_common.bounded import MAX_INPUT_BYTES
from ros_tutorials_common.shutdown import StopSignals
from ros_tutorials_common.wait import Interrupted, ServerLost, spin_until

if TYPE_CHECKING:
    from rclpy.action import ActionClient

# rclpy.action (0.15 s to load: numpy) and the message modules are imported when a goal is
# sent, not to build the parser.

HELP = "Send an action goal"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("action_name", help="Name of the ROS action (e.g. '/fibonacci')")
    parser.add_argument(
        "action_type", help="Type of the ROS action (e.g. 'turtlesim/action/RotateAbsolute')"
    )
    completion.attach(
        parser, action_name=completion.action_names, action_type=completion.types_for_action
    )
    given = parser.add_mutually_exclusive_group()
    given.add_argument(
        "goal",
        nargs="?",
        default="{}",
        help="Goal request values in YAML format (e.g. '{theta: 1.57}')",
    )
    given.add_argument("--stdin", action="store_true", help="Read goal from standard input")
    parser.add_argument(
        "-f", "--feedback", action="store_true", help="Echo feedback messages for the goal"
    )


def main(graph: Graph, args: argparse.Namespace) -> None:
    send_goal(graph, args.action_name, args.action_type, _goal_values(args), args.feedback)


def _goal_values(args: argparse.Namespace) -> Any:
    """The goal's YAML: the argument ('{}' if none), or with --stdin what stdin holds."""
    text = args.goal
    if args.stdin:
        try:
            text = sys.stdin.read(MAX_INPUT_BYTES + 1)
        except UnicodeDecodeError:
            raise ToolError("standard input is not text (not UTF-8)") from None
        if len(text) > MAX_INPUT_BYTES:
            raise ToolError("standard input holds more than 1 MiB; refusing it")
    from ros2cmd.messages import parse_yaml

    return parse_yaml(text)


class _OtherTypes:
    """Called while send_goal waits: true once the action's servers are seen to offer only
    other types than the one wanted (then ``seen`` holds them). Asks the graph at most every
    CHECK_PERIOD seconds."""

    CHECK_PERIOD = 0.25

    def __init__(self, graph: Graph, action: str, wanted: str):
        self.graph, self.action, self.wanted = graph, action, wanted
        self.seen: list[str] = []
        self.next_check = 0.0

    def __call__(self) -> bool:
        now = time.monotonic()
        if now < self.next_check:
            return False
        self.next_check = now + self.CHECK_PERIOD
        types = server_types(self.graph, self.action)
        if types and self.wanted not in types:
            self.seen = types
        return bool(self.seen)


def _block(title: str, msg: Any, indent: str = "    ") -> str:
    # ros2action prints `Title:\n    ` + the YAML (which ends with a newline) + print's own
    # newline: the first line indented, a blank line after.
    from ros2cmd.messages import message_to_yaml

    return f"{title}:\n{indent}{message_to_yaml(msg)}\n"


def send_goal(
    graph: Graph, action: str, type_name: str, values: Any, feedback: bool = False
) -> None:
    """Send one goal, print feedback if asked, wait for the result however long it takes.

    Ctrl-C cancels the goal on the server (waiting a bounded time for it to confirm), then
    raises Interrupted (exit status 130). A server that goes away is a ToolError.
    """
    from rclpy.action import ActionClient

    from ros2cmd.messages import fill_message

    action = absolute_name(action)
    action_type = load_type(type_name, ("action",))
    goal = fill_message(action_type.Goal(), values)
    client = ActionClient(graph.node, action_type, action)

    # Feedback can come in the same spin as the server's acceptance, before this has printed
    # `Goal accepted`: keep it until then, so that the blocks come in ros2action's order.
    early: list[Any] | None = []

    def on_feedback(message: Any) -> None:
        if early is not None:
            early.append(message)
        else:
            print(_block("Feedback", message.feedback), flush=True)

    # While the goal is ours, Ctrl-C only sets a flag: ROS must keep running to cancel it.
    ctrl_c = StopSignals((signal.SIGINT,), second_raises=True)

    def interrupted() -> bool:
        return bool(ctrl_c.received)

    sent = result = None
    try:
        print("Waiting for an action server to become available...", flush=True)
        # A server of another type is never ready for this client: say so once it is seen.
        wanted = full_type_name(action_type)
        other_types = _OtherTypes(graph, action, wanted)
        found = spin_until(
            graph.executor,
            lambda: client.server_is_ready() or other_types(),
            graph.timeout,
            interrupted=interrupted,
        )
        if not found:
            raise ToolError(f"no action server for '{action}' (waited {graph.timeout:g} s)")
        if other_types.seen:
            raise ToolError(
                f"action '{action}' has type {', '.join(other_types.seen)}, not {wanted} "
                f"(`ros2 action type {action}` says its type)"
            )
        print(_block("Sending goal", goal, indent="     "), flush=True)
        sent = client.send_goal_async(goal, feedback_callback=on_feedback if feedback else None)
        # From now on the server must stay (client=): one that crashed would never answer.
        if not spin_until(
            graph.executor, sent.done, graph.timeout, client=client, interrupted=interrupted
        ):
            raise ToolError(f"no answer to the goal from '{action}' (waited {graph.timeout:g} s)")
        goal_handle = sent.result()
        if not goal_handle.accepted:
            raise ToolFailure("Goal was rejected.")
        print(f"Goal accepted with ID: {bytes(goal_handle.goal_id.uuid).hex()}\n", flush=True)
        waiting, early = early, None
        for message in waiting:
            on_feedback(message)
        result = goal_handle.get_result_async()
        # A goal may run for long: no timeout; Ctrl-C or a lost server ends the wait.
        spin_until(graph.executor, result.done, client=client, interrupted=interrupted)
    except Interrupted:
        _cancel(graph, client, sent)
        raise
    except ServerLost:
        raise ToolError(
            f"the action server of '{action}' went away before the goal finished"
        ) from None
    finally:
        ctrl_c.restore()
    answer = result.result()
    status = status_name(answer.status)
    if status == "SUCCEEDED":
        graph.finish()
    print(_block("Result", answer.result))
    print(f"Goal finished with status: {status}", flush=True)
    if status != "SUCCEEDED":
        raise ToolError(f"the goal did not succeed: {status}")


def _cancel(graph: Graph, client: ActionClient, sent: Any) -> None:
    """After Ctrl-C: cancel the goal if the server took it, in ros2action's words."""
    response = cancel_goal(
        graph.executor, client, sent, lambda: print("Canceling goal...", flush=True)
    )
    if sent is None or not sent.done() or not sent.result().accepted:
        return  # nothing was running on the server
    if response is None:
        print("error: no answer to the cancel request", file=sys.stderr, flush=True)
    elif not response.goals_canceling:
        print("error: Failed to cancel goal", file=sys.stderr, flush=True)
    else:
        print("Goal canceled.", flush=True)
