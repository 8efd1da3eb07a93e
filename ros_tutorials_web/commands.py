"""The rqt commands: ``rqt`` and its plugins' own commands open the browser view at that tool
(rqt.py, static/rqt.html): a browser window where there is a display, and the printed link
where there is none; each serves until Ctrl-C, as rqt's window stays until closed.
``ros2 run rqt_X rqt_X`` and ``rosrun rqt_X rqt_X`` run these.

    rqt                            every plugin (the Plugins menu: a tab each)
    rqt_service_caller             Service Caller
    rqt_publisher                  Message Publisher
    rqt_reconfigure                Parameters (dynamic reconfigure)
    rqt_logger_level               Logger levels; with NODE [LEVEL], or down a pipe, the
                                   terminal form
    rqt_plot [TOPIC/FIELD ...]     Plot, of these fields
    rqt_bag [BAG]                  Bag, this bag opened
    rqt_console                    the viewer's log panel; with filters, or down a pipe, the
                                   terminal form
    rqt_graph                      a window where there is a display (its own); else the
                                   viewer's graph, or DOT when stdout is not a terminal;
                                   -o FILE writes a picture (ros2cmd.ros1.rqt)

Each takes the viewer's --port, --host and --allow-origin.
"""

from __future__ import annotations

import argparse
import os
import sys
import urllib.parse
import webbrowser
from collections.abc import Callable, Sequence

from ros2cmd.ros1 import rqt as terminal
from ros_tutorials_common import completion
from ros_tutorials_common.ros import user_args
from ros_tutorials_common.shutdown import program_main
from ros_tutorials_web import guard, viewer


def has_display() -> bool:
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def open_window(link: str) -> None:
    """A browser window at the link, where there is a display (the link is printed anyway)."""
    if has_display():
        webbrowser.open(link, new=1)


def _parser(prog: str, description: str) -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog=prog, description=description)
    guard.add_arguments(parser)
    return parser


def _browser(
    prog: str,
    description: str,
    fragment: str,
    more: Callable[[argparse.ArgumentParser], None] | None = None,
    extra: Callable[[argparse.Namespace], str] | None = None,
) -> Callable[[Sequence[str] | None], int]:
    """A command that serves the view and opens it at /rqt#fragment (+ what extra adds)."""

    @program_main
    def command(argv: Sequence[str] | None = None) -> int:
        full = list(sys.argv if argv is None else [prog, *argv])
        parser = _parser(prog, description)
        if more is not None:
            more(parser)
        completion.answer(parser)  # the shell asking for TAB's completions: answered, ends here
        args = parser.parse_args(user_args(full))
        path = "/rqt#" + fragment + (extra(args) if extra is not None else "")
        return viewer.serve(full, args, path, f"rqt_gui_py_node_{os.getpid()}", open_window)

    return command


rqt = _browser("rqt", "rqt's plugins in the browser", "service_caller")
rqt_service_caller = _browser("rqt_service_caller", "Call a service", "service_caller")
rqt_publisher = _browser("rqt_publisher", "Publish messages", "publisher")
rqt_reconfigure = _browser("rqt_reconfigure", "Change nodes' parameters", "reconfigure")


def _plot_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("fields", nargs="*", metavar="TOPIC/FIELD", help="e.g. /turtle1/pose/x")


def _plot_fragment(args: argparse.Namespace) -> str:
    return (":" + urllib.parse.quote(",".join(args.fields), safe="/,")) if args.fields else ""


rqt_plot = _browser("rqt_plot", "Plot numeric fields", "plot", _plot_arguments, _plot_fragment)


def _bag_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("bag", nargs="?", help="a bag folder or .mcap file to open")


def _bag_fragment(args: argparse.Namespace) -> str:
    if not args.bag:
        return ""
    return ":" + urllib.parse.quote(os.path.abspath(args.bag), safe="/")


rqt_bag = _browser("rqt_bag", "Look into a bag and play it", "bag", _bag_arguments, _bag_fragment)
_logger_levels = _browser("rqt_logger_level", "Nodes' logger levels", "logger_level")
_console_view = _browser("rqt_console", "The /rosout log", "console")
_graph_view = _browser("rqt_graph", "The running graph", "graph")


def _only_server_options(argv: Sequence[str]) -> bool:
    """Whether the command line asks for nothing but where to serve (or is empty)."""
    server_options = argparse.ArgumentParser(add_help=False)  # -h: the terminal form's help
    guard.add_arguments(server_options)
    server_options.error = lambda message: None  # type: ignore[method-assign]
    try:
        _, rest = server_options.parse_known_args(list(argv))
    except (SystemExit, TypeError, ValueError):
        return False
    return not rest


def _given(argv: Sequence[str] | None) -> list[str]:
    return user_args(sys.argv if argv is None else ["", *argv])


def _terminal_form(argv: Sequence[str] | None) -> bool:
    """The terminal form: arguments beyond where to serve, a TAB completion, or a bare
    command whose output goes down a pipe or into a file (`rqt_console | grep wall`)."""
    given = _given(argv)
    if given:
        return not _only_server_options(given)
    return completion.requested() or not sys.stdout.isatty()


def rqt_logger_level(argv: Sequence[str] | None = None) -> int:
    if _terminal_form(argv):
        return terminal.rqt_logger_level(argv)  # every node's level, or NODE [LEVEL]
    return _logger_levels(argv)


def rqt_console(argv: Sequence[str] | None = None) -> int:
    if _terminal_form(argv):
        return terminal.rqt_console(argv)  # the lines in the terminal, filtered if asked
    return _console_view(argv)


def rqt_graph(argv: Sequence[str] | None = None) -> int:
    given = _given(argv)
    browser = not given or _only_server_options(given)
    if browser and not has_display() and sys.stdout.isatty():
        return _graph_view(argv)
    return terminal.rqt_graph(argv)  # -o FILE, a window of its own, or DOT down a pipe
