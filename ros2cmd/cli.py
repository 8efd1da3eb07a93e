"""`ros2 VERB COMMAND ...`: the command line, and how every command runs and fails.

The verbs are ros2cli's (ROS 2 Jazzy), with its sub-verbs, options and output. Each verb lives
in its own package or module (topic/, node.py, ...) and registers its commands here;
`ros2 launch` is the launcher's own command line (launcher/__main__.py), handed over by
entry.py. Building the parser (`build_parser()`, the whole of it, as TAB completion does)
loads no rclpy: the verbs import it where a command runs, so help, parsing and the daemon's
answers go without it (tests/test_cli_imports.py); `ros2 VERB ...` builds its verb's parser
alone. A command is a function of the graph and the parsed arguments. `execute` gives all of them
the same behaviour: a ToolError or a bad name prints one line and exits 1, Ctrl-C exits 130
(EXIT_INTERRUPTED), except in the verbs that run until Ctrl-C (`echo`, `hz`, `bw`, `pub` with
a rate or latched), for which it is the normal end: 0 (see graph.until_stopped).
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import signal
import sys
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from ros2cmd.errors import ToolError, rclpy_error
from ros2cmd.sub_verbs import VERB_HELP
from ros_tutorials_common import shutdown
from ros_tutorials_common.cli import EXIT_INTERRUPTED, JazzyArgumentParser, positive_seconds
from ros_tutorials_common.dds import environment_problem
from ros_tutorials_common.wait import Interrupted

if TYPE_CHECKING:
    from ros2cmd.graph import Graph

# The graph and the daemon's client are imported where a command needs them: `ros2 run`
# (offline, and replaced by the node at once) loads neither.


def common_options() -> argparse.ArgumentParser:
    """Options every graph command takes (added to each command so they go after it)."""
    from ros2cmd.graph import DEFAULT_TIMEOUT, MAX_SETTLE_TIME

    common = argparse.ArgumentParser(add_help=False)
    common.add_argument(
        "--timeout",
        type=positive_seconds,
        default=DEFAULT_TIMEOUT,
        help=f"seconds to wait for what the command names to appear (default {DEFAULT_TIMEOUT:g})",
    )
    common.add_argument(
        "--spin-time",
        type=positive_seconds,
        help="seconds a list waits for discovery (default: until every participant's "
        "announced nodes and endpoints are seen, "
        f"at most {MAX_SETTLE_TIME:g})",
    )
    common.add_argument(
        "--no-daemon",
        action="store_true",
        help="Do not spawn nor use an already running daemon",
    )
    return common


# The verbs that take a command (`ros2 topic list`), unlike `run` and `launch`.
VERBS_WITH_COMMANDS = frozenset(
    {"action", "bag", "daemon", "interface", "node", "param", "pkg", "service", "topic"}
)
# `ros2 launch` is the launcher: its own parser, options and process (entry.py hands it over;
# here it is only its line in `ros2 -h`, sub_verbs.VERB_HELP).


# Each verb's module, whose register(verbs, common) adds its parser, in the order they are
# registered (argparse names the choices in that order); `wtf` is doctor's alias.
VERB_MODULES = {
    "action": "ros2cmd.action",
    "bag": "ros2cmd.bag.ros2",
    "daemon": "ros2cmd.daemon",
    "doctor": "ros2cmd.doctor",
    "wtf": "ros2cmd.doctor",
    "interface": "ros2cmd.interface",
    "node": "ros2cmd.node",
    "param": "ros2cmd.param",
    "pkg": "ros2cmd.pkg",
    "run": "ros2cmd.run",
    "service": "ros2cmd.service",
    "topic": "ros2cmd.topic",
}


def build_parser(verb: str | None = None) -> argparse.ArgumentParser:
    """The whole `ros2` parser, every verb and its options (cheap: no rclpy, no messages).

    With a verb of VERB_MODULES, that verb's parser alone: `ros2 VERB ...` parses, helps and
    fails with it as with the whole one, without loading the other verbs' modules.
    """
    parser, verbs = _ros2_parser()
    if verb is None:
        verbs.add_parser("launch", help=VERB_HELP["launch"], add_help=False)
    # `run` takes no graph options (and would load the graph's module for their defaults).
    common = argparse.ArgumentParser(add_help=False) if verb == "run" else common_options()
    wanted = VERB_MODULES.values() if verb is None else [VERB_MODULES[verb]]
    for module in dict.fromkeys(wanted):
        importlib.import_module(module).register(verbs, common)
    verbs._choices_actions.sort(key=lambda choice: choice.dest)  # ros2cli lists them a-z
    return parser


def help_parser() -> argparse.ArgumentParser:
    """What `ros2` and `ros2 -h` print: the verbs' lines (VERB_HELP) with no verb's module
    loaded; the same help as build_parser()'s (tests/test_cli_imports.py)."""
    parser, verbs = _ros2_parser()
    for verb in sorted(VERB_HELP):
        verbs.add_parser(verb, help=VERB_HELP[verb], add_help=False)
    return parser


def _ros2_parser() -> tuple[argparse.ArgumentParser, argparse._SubParsersAction]:
    parser = JazzyArgumentParser(  # its verbs' and their commands' parsers are JazzyArgumentParser
        prog="ros2",
        description="ros2 is an extensible command-line tool for ROS 2.",
        epilog="Call `ros2 <command> -h` for more detailed usage.",
    )
    verbs = parser.add_subparsers(dest="verb", title="Commands", metavar="Commands", required=True)
    return parser, verbs


def execute(
    command: Callable[[Graph | None], None],
    offline: bool = False,
    timeout: float | None = None,
    spin_time: float | None = None,
    use_daemon: bool | dict[str, Any] = False,
) -> int:
    """Run one command with a graph node (unless offline); map failures to exit codes.

    timeout: what the command waits for what it names (None: graph.DEFAULT_TIMEOUT).

    With use_daemon (the lists; a dict: what else to ask, daemon.ask_graph), the daemon's
    complete answer stands in for the node where one runs and can give it (daemon/), and
    holds what the command names; otherwise the command discovers for itself.

    Meant for a process's main: once the status is decided, Ctrl-C is ignored. Python and
    DDS still take about 0.3 s to shut down, and a Ctrl-C then would kill the process by
    SIGINT (a shell shows 130) after the command had printed its answer.
    """
    try:
        return _execute(command, offline, timeout, spin_time, use_daemon)
    except KeyboardInterrupt:  # while an error line was being printed
        return EXIT_INTERRUPTED


def _execute(
    command: Callable[[Graph | None], None],
    offline: bool,
    timeout: float | None,
    spin_time: float | None,
    use_daemon: bool | dict[str, Any] = False,
) -> int:
    graph = None
    status = None  # the exit status, once decided
    try:
        problem = None if offline else environment_problem()
        if problem:  # rcl would fail with a traceback, or Fast DDS with its own lines
            raise ToolError(problem)
        answered = False
        if use_daemon and spin_time is None:
            from ros2cmd.daemon import client as daemon

            graph = daemon.ask_graph(use_daemon if isinstance(use_daemon, dict) else {})
            if graph is not None:
                try:
                    command(graph)
                    answered = True
                except daemon.NotInAnswer:  # before printing: the command waits for it itself
                    graph = None
        if not answered:
            if not offline:
                from ros2cmd.graph import DEFAULT_TIMEOUT, Graph

                graph = Graph(DEFAULT_TIMEOUT if timeout is None else timeout, spin_time)
            command(graph)
        status = 0
    except ToolError as error:
        print(f"{error.prefix}{error}", file=sys.stderr)
        status = 1
    except rclpy_error("rclpy.exceptions", "NameValidationException") as error:
        print(f"error: {str(error).splitlines()[0]}", file=sys.stderr)
        status = 1
    except (
        KeyboardInterrupt,
        Interrupted,
        *rclpy_error("rclpy.executors", "ExternalShutdownException"),
    ):
        status = 0 if graph is not None and graph.finished else EXIT_INTERRUPTED
    except Exception as error:
        status = shutdown.output_failed(error)  # `| head` (0), `> /dev/full` (one line, 1)
        if status is not None:
            pass
        elif shutdown.interrupted(error) and _ros_ok():
            # An error a Ctrl-C caused on its way up (the KeyboardInterrupt in its context:
            # rclpy code cleaning up after it raised anew): the Ctrl-C it is.
            status = 0 if graph is not None and graph.finished else EXIT_INTERRUPTED
        elif _ros_ok() or "rclpy" not in sys.modules:
            raise
        else:
            # SIGTERM: rclpy's handler shut ROS down while the command was creating its node,
            # a subscription or a timer, which then fails (RCLError "context is not valid").
            status = EXIT_INTERRUPTED
    finally:
        if status is not None:
            # Decided: from here on a Ctrl-C (the user answering the printed line while the
            # node closes and Python shuts down, however late the process gets the CPU back)
            # does not turn a command that did its job into "interrupted". (Not when an
            # exception goes on up, such as argparse's exit: the caller's Ctrl-C stays.)
            signal.signal(signal.SIGINT, signal.SIG_IGN)
        if graph is not None:
            with contextlib.suppress(KeyboardInterrupt):  # only if nothing was decided
                graph.close()
    return status


def _ros_ok() -> bool:
    """rclpy.ok(): False where rclpy was never loaded (nothing initialised it)."""
    rclpy = sys.modules.get("rclpy")
    return rclpy is not None and rclpy.ok()


def main(argv: Sequence[str] | None = None) -> int:
    words = list(sys.argv[1:] if argv is None else argv)
    if words in ([], ["-h"], ["--help"]):
        help_parser().parse_args(["--help"])
    parser = build_parser(words[0] if words[:1] and words[0] in VERB_MODULES else None)
    if not words or (len(words) == 1 and words[0] in VERBS_WITH_COMMANDS):
        # As ros2cli: `ros2` or `ros2 topic` alone prints the help and ends well.
        parser.parse_args([*words, "--help"])
    return run_parsed(parser.parse_args(words))


def run_parsed(args: argparse.Namespace) -> int:
    """Run the command a parser chose (ros2's, or a ROS 1 tool's in ros1/)."""
    return execute(
        lambda graph: args.run(graph, args),
        offline=getattr(args, "offline", False),
        timeout=getattr(args, "timeout", None),
        spin_time=getattr(args, "spin_time", None),
        use_daemon=_wants_daemon(args),
    )


def _wants_daemon(args: argparse.Namespace) -> bool | dict[str, Any]:
    """Whether the daemon can answer the command (its parser says, perhaps by looking at the
    options: `topic list -v` counts endpoints, which only a node can), and what else to ask
    it (a dict: `node info` asks for the node's endpoints, daemon.ask_graph)."""
    wants = getattr(args, "daemon", False)
    wants = wants(args) if callable(wants) else wants
    if not wants:
        return False
    from ros2cmd.daemon import client as daemon

    if not daemon.use_daemon(getattr(args, "no_daemon", False)):
        return False
    return wants if isinstance(wants, dict) else True
