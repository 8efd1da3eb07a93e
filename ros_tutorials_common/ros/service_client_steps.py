"""What the service lessons' clients do besides the book's steps; a learner can skip this.

The book's client reads two numbers, calls the service and logs the answer. A command line
has to do more: refuse bad arguments with a usage line (exit status 2), give up on a server
that is not there or does not answer (exit status 1, one ``Failed to call service`` line),
and stop at Ctrl-C (exit status 130). Those parts live here, so the lesson file shows the
book's steps: ``rclpy.init``, the node, the client, the request, ``call_async``, the answer::

    options = parse_args(args, "service_client", "A", "B")
    ...
    if not wait_for_service(node, client, options.timeout):
        return 1
    future = client.call_async(request)
    if not wait_for_answer(node, client, future, options.timeout):
        return 1
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Sequence

import rclpy
from rclpy.client import Client
from rclpy.node import Node
from rclpy.task import Future

from ros_tutorials_common.cli import EXIT_INTERRUPTED, positive_seconds, signed_int
from ros_tutorials_common.ros.node_main import ros_args, user_args

__all__ = ["interrupted", "parse_args", "ros_args", "wait_for_answer", "wait_for_service"]
SPIN_SLICE = 0.1  # seconds: how long one spin may block, so that Ctrl-C is seen in between


def parse_args(
    args: Sequence[str] | None, prog: str, first: str, second: str, default_timeout: float = 5.0
) -> argparse.Namespace:
    """The client's command line (sys.argv unless args, without the ROS arguments): two int64
    operands, named ``first`` and ``second`` (lower case in the result), and ``--timeout``.
    Anything else prints the usage and ends the program with exit status 2."""
    parser = argparse.ArgumentParser(
        prog=prog,
        description=f"Call the service once with {first} and {second}, and log the answer.",
        epilog="exit status: 0 answered; 1 no server, or no answer, within --timeout seconds; "
        "2 usage error; 130 Ctrl-C",
    )
    for name, which in ((first, "first"), (second, "second")):
        parser.add_argument(
            name.lower(), metavar=name, type=signed_int(64), help=f"{which} operand (int64)"
        )
    parser.add_argument(
        "--timeout", metavar="SECONDS", type=positive_seconds, default=default_timeout,
        help=f"how long to wait for the server, then for its answer (default {default_timeout:g})",
    )  # fmt: skip
    return parser.parse_args(user_args(args))


def wait_for_service(node: Node, client: Client, timeout: float) -> bool:
    """client.wait_for_service, saying so if it takes more than a second; False (and one error
    line) if no server came within ``timeout`` seconds."""
    if client.wait_for_service(timeout_sec=min(1.0, timeout)):
        return True
    log = node.get_logger()
    if timeout > 1.0:
        log.info(f"waiting for service {client.srv_name} (up to {timeout:g} s)...")
        if client.wait_for_service(timeout_sec=timeout - 1.0):
            return True
    log.error(f"Failed to call service {client.srv_name}: no server within {timeout:g} s")
    return False


def wait_for_answer(node: Node, client: Client, future: Future, timeout: float) -> bool:
    """Spin the node until the future is done (True), in short slices so that Ctrl-C is seen
    between two; False (and one error line) if no answer came within ``timeout`` seconds."""
    end = time.monotonic() + timeout
    while not future.done() and time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=SPIN_SLICE)
    if not future.done():
        node.get_logger().error(
            f"Failed to call service {client.srv_name}: no answer within {timeout:g} s"
        )
    return future.done()


def interrupted(prog: str) -> int:
    """Say that Ctrl-C ended the program; its exit status (130, as shells report it)."""
    print(f"{prog}: interrupted", file=sys.stderr)
    return EXIT_INTERRUPTED
