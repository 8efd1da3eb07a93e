"""rviz2: the 3D view, in a browser (rviz2 itself is C++ and Qt, not on PyPI).

    rviz2                                   # grid, tf frames, the robot on /robot_description
    rviz2 -d FILE.rviz                      # the file's fixed frame and displays
    ros2 run rviz2 rviz2 -d $(ros2 pkg prefix --share turtle_tf2_py)/rviz/turtle_rviz.rviz
    rviz2 -f base_link                      # this fixed frame
    rviz                                    # ROS 1's name for it

It opens the view in a browser window where there is a display, and prints the link either way
(the link carries a token made for this run: the page, its WebSocket and its files are guarded
as the web viewer's are). A .rviz file's displays that the view does not draw are named, one
line each; a file that is not a .rviz file is one line and exit 1.

With no file, the view also adds a display for every topic of a type it draws (as rviz's "Add
by topic"), and chooses the fixed frame: map, world or odom when tf has one, else the root of
the largest tree. docs/rviz-in-the-browser.md shows it; docs/dev/rviz.md says how it is built.
"""

from __future__ import annotations

import argparse
import asyncio
import os
import sys
import threading
import webbrowser
from collections.abc import Sequence

DEFAULT_PORT = 8090  # when free; else any free port


def parse_args(argv: Sequence[str], prog: str) -> argparse.Namespace:
    from ros_tutorials_web.viewer import DEFAULT_HOST, origin, port_number

    parser = argparse.ArgumentParser(
        prog=prog, description="rviz2's 3D view in a browser: tf, robot model, markers, sensors"
    )
    parser.add_argument(
        "-d", "--display-config", metavar="FILE", help="a .rviz file: fixed frame and displays"
    )
    parser.add_argument("-f", "--fixed-frame", metavar="FRAME", help="the fixed frame")
    # rviz2's options that mean nothing in a browser are accepted and ignored.
    parser.add_argument("-s", "--splash-screen", metavar="FILE", help=argparse.SUPPRESS)
    parser.add_argument("-l", "--ogre-log", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--fullscreen", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument(
        "--port",
        type=port_number,
        help=f"the port of the page (default {DEFAULT_PORT}, or a free one if it is taken)",
    )
    parser.add_argument(
        "--host", default=DEFAULT_HOST, help=f"the address to listen on (default {DEFAULT_HOST})"
    )
    parser.add_argument(
        "--allow-origin",
        action="append",
        default=[],
        type=origin,
        metavar="ORIGIN",
        dest="allow_origins",
        help="also accept the page shown from ORIGIN (a cloud editor's forwarded port)",
    )
    return parser.parse_args(argv)


def open_window(url: str) -> bool:
    """Open URL in a browser window where there is a display: the learner's $BROWSER, or a
    browser that opens a window of its own (never a text browser, which would take the
    terminal). In a thread: a browser command that runs until its window closes holds
    nothing up. False where none opens."""
    if not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
        return False
    try:
        browser = webbrowser.get()
    except webbrowser.Error:
        return False
    windowed = isinstance(browser, webbrowser.BackgroundBrowser) or getattr(
        browser, "background", False
    )
    if not (windowed or os.environ.get("BROWSER")):
        return False
    threading.Thread(target=browser.open, args=(url,), daemon=True).start()
    return True


def main(argv: Sequence[str] | None = None, prog: str = "rviz2") -> int:
    from rclpy.signals import SignalHandlerOptions

    from ros_tutorials_common import packages
    from ros_tutorials_common.ros import init, user_args
    from ros_tutorials_web.viewer import Guard, greeting, link, listen
    from rviz2.config import ConfigError, default_config, load
    from rviz2.scene import Scene
    from rviz2.server import serve

    argv = list(sys.argv if argv is None else argv)
    args = parse_args(user_args(argv), prog)
    try:
        config = load(args.display_config) if args.display_config else default_config()
    except ConfigError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    if args.fixed_frame:
        config.fixed_frame = args.fixed_frame
    for line in config.lacking:
        print(f"warning: {line}", file=sys.stderr, flush=True)
    if args.port is None:
        try:
            sock = listen(args.host, DEFAULT_PORT)
        except SystemExit:  # taken: any free port will do (a bad --host says so again)
            sock = listen(args.host, 0)
    else:
        sock = listen(args.host, args.port)
    guard = Guard.for_socket(sock, args.host, args.allow_origins)

    def make_scene(handoff):
        return Scene(config, handoff, packages.share_directory, by_topic=not args.display_config)

    def ready(scene: Scene) -> None:
        logger = scene.get_logger()
        first, *warnings = greeting(sock, guard)
        address, port = sock.getsockname()[:2]
        local = link("127.0.0.1" if address in ("0.0.0.0", "::") else address, port, guard.token)
        logger.info(first)
        for line in warnings:
            logger.warning(line.replace("the viewer publishes nothing", "rviz2 publishes nothing"))
        open_window(local)

    import rclpy

    try:
        init(argv, signal_handler_options=SignalHandlerOptions.NO)
        asyncio.run(serve(sock, guard, make_scene, ready))
    except KeyboardInterrupt:
        pass
    finally:
        sock.close()
        rclpy.try_shutdown()
    return 0


def rviz(argv: Sequence[str] | None = None) -> int:
    """ROS 1's ``rviz``: the same view (``-d`` and ``-f`` as rviz has them)."""
    return main(argv, prog="rviz")


if __name__ == "__main__":
    sys.exit(main())
