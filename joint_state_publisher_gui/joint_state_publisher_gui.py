"""`ros2 run joint_state_publisher_gui joint_state_publisher_gui [URDF_FILE]`: sliders for the
robot's joints, in the browser.

ROS 2's joint_state_publisher_gui is joint_state_publisher (same node name, parameters and
topics) with a Qt window: a slider per movable joint that is not a mimic, from its lower to its
upper limit, its value shown to three decimals, and the buttons Randomize and Center. Here the
window is a web page: the node logs the link to open ("Open http://127.0.0.1:PORT/?token=..."),
and opens it in a browser window where there is a display.
The page and its WebSocket are behind the guard of this project's web tools (a token made for
this run, the Host and Origin checks: ros_tutorials_web/guard.py); a slider moved in any open
tab moves it in every tab, and values from ``source_list`` topics move the sliders.

A message from the page that does not fit (an unknown joint, a value that is not a number) is
one line in the page, and nothing changes; a value outside the joint's limits is held at the
limit. ``--port``, ``--host``, ``--allow-origin`` as the viewer's.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import math
import random
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from aiohttp import WSMsgType, web

from joint_state_publisher.joint_state_publisher import JointStatePublisher, StartError
from ros_tutorials_common.ros.node_main import user_args
from ros_tutorials_common.shutdown import program_main
from ros_tutorials_web import guard, server
from ros_tutorials_web.commands import open_window

STATIC = Path(__file__).resolve().parent / "static"
DEFAULT_PORT = 8081
MAX_MESSAGE = 64 * 1024  # bytes of one message from a page
EXPOSED = "move this robot's joints (publish on /joint_states)"


class Sliders:
    """The sliders' state, shared by every open tab: joint_state_publisher's free joints."""

    def __init__(self, jsp: JointStatePublisher, loop: asyncio.AbstractEventLoop) -> None:
        self.jsp = jsp
        self.loop = loop
        self.tabs: set[web.WebSocketResponse] = set()
        self.outbox: dict[web.WebSocketResponse, dict[str, str]] = {}  # kind -> newest text
        self.sending: set[web.WebSocketResponse] = set()
        jsp.set_robot_description_update_cb(lambda: self.from_ros(self.joints))
        jsp.set_source_update_cb(lambda: self.from_ros(self.positions))

    def from_ros(self, message: Any) -> None:
        """Called in ROS's thread: send ``message()`` to every tab from the event loop."""
        self.loop.call_soon_threadsafe(lambda: self.send_all(message()))

    def joints(self) -> dict[str, Any]:
        """The sliders to draw: every free joint in the file's order, as the Qt window has."""
        free = self.jsp.free_joints
        return {
            "robot": True,
            "joints": [
                {
                    "name": name,
                    "min": free[name]["min"],
                    "max": free[name]["max"],
                    "zero": free[name]["zero"],
                    "position": free[name].get("position", free[name]["zero"]),
                }
                for name in self.jsp.joint_list
                if name in free
            ],
        }

    def positions(self) -> dict[str, Any]:
        free = self.jsp.free_joints
        return {"positions": {n: j.get("position", j["zero"]) for n, j in free.items()}}

    def send_all(self, message: dict[str, Any]) -> None:
        """Offer every tab the message; a tab that reads slowly gets the newest of each kind
        (a robot, positions), never a backlog: one waiting message per kind and tab."""
        kind = "joints" if "joints" in message else "positions"
        text = json.dumps(message)
        for tab in list(self.tabs):
            box = self.outbox.setdefault(tab, {})
            if kind == "joints":
                box.clear()  # a new robot: older positions are of the old one
            box[kind] = text
            if tab not in self.sending:
                self.sending.add(tab)
                self.loop.create_task(self._drain(tab, box))

    async def _drain(self, tab: web.WebSocketResponse, box: dict[str, str]) -> None:
        try:
            while box and not tab.closed:
                for kind in ("joints", "positions"):
                    text = box.pop(kind, None)
                    if text is not None:
                        await tab.send_str(text)
        except (ConnectionError, RuntimeError):
            pass  # the tab went away: its handler forgets it
        finally:
            self.sending.discard(tab)

    def change(self, request: Any) -> tuple[dict[str, Any] | None, str | None]:
        """Apply one request of a page: (what every tab must hear, or an error line)."""
        if not isinstance(request, dict) or len(request) != 1:
            return None, 'a message is one of {"set": {JOINT: VALUE}}, {"center": true}, ...'
        ((what, value),) = request.items()
        free = self.jsp.free_joints
        if what == "center":
            self.jsp.get_logger().info("Centering")
            for joint in free.values():
                joint["position"] = joint["zero"]
        elif what == "randomize":
            self.jsp.get_logger().info("Randomizing")
            for joint in free.values():
                joint["position"] = random.uniform(joint["min"], joint["max"])
        elif what == "set" and isinstance(value, dict):
            checked = {}
            for name, position in value.items():
                if name not in free:
                    return None, f"no movable joint named {str(name)[:80]!r}"
                if isinstance(position, bool) or not isinstance(position, int | float):
                    return None, f"{name}: the position must be a number, not {position!r:.40}"
                if not math.isfinite(position):
                    return None, f"{name}: the position must be a finite number"
                joint = free[name]
                checked[name] = min(max(float(position), joint["min"]), joint["max"])
            for name, position in checked.items():
                free[name]["position"] = position
        else:
            return None, f"unknown request {what[:40]!r}: set, center or randomize"
        return self.positions(), None

    async def tab(self, request: web.Request) -> web.WebSocketResponse:
        ws = web.WebSocketResponse(heartbeat=20, max_msg_size=MAX_MESSAGE)
        await ws.prepare(request)
        self.tabs.add(ws)
        try:
            await ws.send_str(json.dumps(self.joints()))
            async for message in ws:
                if message.type != WSMsgType.TEXT:
                    continue
                try:
                    asked = json.loads(message.data)
                except ValueError:
                    await ws.send_str(json.dumps({"error": "a message must be JSON"}))
                    continue
                changed, error = self.change(asked)
                if error is not None:
                    await ws.send_str(json.dumps({"error": error}))
                else:
                    self.send_all(changed)
        finally:
            self.tabs.discard(ws)
            self.outbox.pop(ws, None)
        return ws

    async def close(self, _app: web.Application) -> None:
        for ws in list(self.tabs):
            await ws.close()


async def page(_request: web.Request) -> web.FileResponse:
    return web.FileResponse(STATIC / "sliders.html")


def parse_args(argv: Sequence[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="joint_state_publisher_gui",
        description="Sliders for a robot's movable joints, in the browser; publishes "
        "/joint_states as joint_state_publisher does.",
    )
    parser.add_argument("urdf_file", nargs="?", default=None, help="URDF file to use")
    guard.add_arguments(parser, default_port=DEFAULT_PORT)
    return parser.parse_args(argv)


@program_main
def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    args = parse_args(user_args(argv))
    sock = guard.listen(args.host, args.port, default_port=DEFAULT_PORT)
    door = guard.Guard.for_socket(sock, args.host, args.allow_origins)

    def make(loop: asyncio.AbstractEventLoop) -> tuple[JointStatePublisher, web.Application]:
        jsp = JointStatePublisher(args.urdf_file)
        sliders = Sliders(jsp, loop)
        app = web.Application(middlewares=[door.middleware(jsp.get_logger().warning)])
        app.on_shutdown.append(sliders.close)
        app.router.add_get("/", page)
        app.router.add_get("/ws", sliders.tab)
        app.router.add_static("/static/", STATIC)
        address, port = sock.getsockname()[:2]
        open_window(
            guard.link("127.0.0.1" if address in guard.WILDCARDS else address, port, door.token)
        )
        return jsp, app

    try:
        return server.run(argv, sock, door, make, exposed=EXPOSED)
    except StartError:
        return 1


if __name__ == "__main__":
    sys.exit(main())
