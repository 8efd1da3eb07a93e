"""How every one-shot tutorial client runs: ``service_client A B`` calls a service once.

A client's main() is one line: ``return call_once(ServiceClient, "service_client")``. The
node class says what to call (its ``client``, made with ``create_client``) and how to report
the answer (its ``report(request, response)``); this helper does the rest, the same way for
every client: read the two 64-bit operands, wait a bounded time for the server, send the
request, wait a bounded time for the answer, and exit with a status a shell can test:

    0    the service answered
    1    the call failed: no server within --timeout, no answer within --timeout
         (or malformed --ros-args)
    2    usage error: wrong number of operands, or operands that are not 64-bit integers
    130  interrupted (Ctrl-C) before the answer came

The wait is a command-line option, ``--timeout SECONDS`` (default 5), rather than a ROS
parameter: it belongs to this one run of the program, and ``-h`` shows it.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Callable, Sequence
from typing import Any, Protocol

import rclpy
from rclpy.client import Client
from rclpy.executors import ExternalShutdownException
from rclpy.impl.implementation_singleton import rclpy_implementation as _rclpy
from rclpy.impl.rcutils_logger import RcutilsLogger

from ros_tutorials_common.cli import EXIT_INTERRUPTED, positive_seconds, signed_int
from ros_tutorials_common.node_main import init, user_args

DEFAULT_TIMEOUT = 5.0
# Discovery usually takes well under a second; only say "waiting" when it takes longer.
QUIET_WAIT = 1.0
POLL_PERIOD = 0.05

EXIT_CALL_FAILED = 1


class OneShotClient(Protocol):
    """A node with a service client and a way to report the answer."""

    client: Client

    def get_logger(self) -> RcutilsLogger: ...

    def report(self, request: Any, response: Any) -> None: ...

    def destroy_node(self) -> None: ...


def parse_operands(
    program: str, operands: tuple[str, str], args: Sequence[str]
) -> argparse.Namespace:
    """The operands (as ``a`` and ``b``) and ``timeout``; exits with usage and status 2 if bad."""
    parser = argparse.ArgumentParser(
        prog=program,
        description="Call the service once with two 64-bit integers and log the answer.",
        epilog="ROS arguments go after --ros-args, e.g. --ros-args -r __ns:=/robot1",
    )
    parser.add_argument("a", metavar=operands[0], type=signed_int(64), help="first operand (int64)")
    parser.add_argument(
        "b", metavar=operands[1], type=signed_int(64), help="second operand (int64)"
    )
    parser.add_argument(
        "--timeout",
        metavar="SECONDS",
        type=positive_seconds,
        default=DEFAULT_TIMEOUT,
        help=f"how long to wait for the server, then for its answer (default {DEFAULT_TIMEOUT:g})",
    )
    return parser.parse_args(args)


def call_once(
    make_node: Callable[[], OneShotClient],
    program: str,
    operands: tuple[str, str] = ("A", "B"),
    argv: Sequence[str] | None = None,
) -> int:
    """Parse the command line, call the node's service once, report. Returns the exit code."""
    argv = list(sys.argv if argv is None else argv)
    args = parse_operands(program, operands, user_args(argv))
    init(argv)
    node = None
    try:
        node = make_node()
        return _call(node, args.a, args.b, args.timeout)
    except (KeyboardInterrupt, ExternalShutdownException):
        print(f"{program}: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


def _call(node: OneShotClient, a: int, b: int, timeout: float) -> int:
    client, log = node.client, node.get_logger()
    if not _wait_for_server(client, timeout, log):
        log.error(f"Failed to call service {client.srv_name}: no server within {timeout:g} s")
        return EXIT_CALL_FAILED

    request = client.srv_type.Request(a=a, b=b)
    future = client.call_async(request)
    # One call, so the few milliseconds spin_until_future_complete costs do not matter.
    rclpy.spin_until_future_complete(node, future, timeout_sec=timeout)
    _raise_if_shut_down(client)
    if not future.done():
        client.remove_pending_request(future)
        log.error(f"Failed to call service {client.srv_name}: no answer within {timeout:g} s")
        return EXIT_CALL_FAILED
    node.report(request, future.result())
    return 0


def _wait_for_server(client: Client, timeout: float, log: RcutilsLogger) -> bool:
    """True once the service has a server; False after timeout seconds without one."""
    # Not Client.wait_for_service: after Ctrl-C (which shuts the context down) it raises
    # RCLError "context is invalid" instead of returning.
    start = time.monotonic()
    said_waiting = False
    while not _server_is_ready(client):
        waited = time.monotonic() - start
        if waited >= timeout:
            return False
        if waited >= QUIET_WAIT and not said_waiting:
            log.info(f"waiting for service {client.srv_name} (up to {timeout:g} s)...")
            said_waiting = True
        time.sleep(POLL_PERIOD)
    return True


def _server_is_ready(client: Client) -> bool:
    _raise_if_shut_down(client)
    try:
        return client.service_is_ready()
    except _rclpy.RCLError:
        _raise_if_shut_down(client)  # the signal came between the check and the call
        raise


def _raise_if_shut_down(client: Client) -> None:
    # Ctrl-C and SIGTERM shut the rclpy context down; end the wait as interrupted.
    if not client.context.ok():
        raise ExternalShutdownException()
