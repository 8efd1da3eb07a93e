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
import sys
from collections.abc import Sequence

from ros_tutorials_common.shutdown import program_main

DEFAULT_PORT = 8090  # when free; else any free port
EXPOSED = "see the tf frames, the robot and every topic the 3D view shows (rviz2 publishes nothing)"


def parse_args(argv: Sequence[str], prog: str) -> argparse.Namespace:
    from ros_tutorials_web import guard

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
    guard.add_arguments(parser, default_port=DEFAULT_PORT)
    return parser.parse_args(argv)


@program_main
def main(argv: Sequence[str] | None = None, prog: str = "rviz2") -> int:
    from aiohttp import web

    from ros_tutorials_common import packages
    from ros_tutorials_common.ros import user_args
    from ros_tutorials_web import guard, server
    from ros_tutorials_web.commands import open_window
    from ros_tutorials_web.hub import Hub
    from rviz2.config import ConfigError, default_config, load
    from rviz2.scene import Scene
    from rviz2.server import deliver, make_app

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
    sock = guard.listen(args.host, args.port, default_port=DEFAULT_PORT)
    door = guard.Guard.for_socket(sock, args.host, args.allow_origins)

    def make(loop: asyncio.AbstractEventLoop) -> tuple[Scene, web.Application]:
        hub = Hub(loop)
        scene = Scene(
            config,
            lambda stream, payload: hub.from_ros(deliver, hub, stream, payload),
            packages.share_directory,
            by_topic=not args.display_config,
        )
        hub.ros = scene.request
        app = make_app(hub, scene, door)
        address, port = sock.getsockname()[:2]
        local = "127.0.0.1" if address in guard.WILDCARDS else address
        link = guard.link(local, port, door.token)
        # A window where there is a display, once the server listens (the link is printed).
        app.on_startup.append(lambda _app: loop.run_in_executor(None, open_window, link))
        return scene, app

    return server.run(argv, sock, door, make, exposed=EXPOSED)


if __name__ == "__main__":
    sys.exit(main())
