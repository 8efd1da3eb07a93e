"""rviz2's web side: the 3D view's page, its files (three.js among them), its WebSocket and the
robot model's mesh files, on ros_tutorials_web's guard (guard.py: a token made for this run,
the Host and Origin checks; 127.0.0.1 unless asked otherwise), hub (hub.py: each stream's
newest payload, kept for tabs to come) and server (server.py: aiohttp beside the node, Ctrl-C
and SIGTERM).

HTTP: ``/`` the page (rviz.html), ``/static/...`` its files, ``/ws`` the WebSocket,
``/mesh/N/I/NAME`` mesh I of display N's robot model (only a file the current model names).

WebSocket, server to browser: the scene's streams (scene.py): ``config``, ``tf`` and one per
display (``display:N``), as JSON text or, with bulk data, binary frames (a 4-byte big-endian
length, that many bytes of JSON, the data). The streams are the display's, not the tab's: the
scene subscribes for its displays whether or not a page looks (as rviz2 does), and every tab
gets every stream. Each tab gets the newest payload of each stream that it has not got yet: a
slow tab misses updates, the server queues none. Browser to server, JSON: ``{"fixed":
FRAME}`` (``""``: the view chooses), ``{"enable": [N, true|false]}``, ``{"add": TOPIC}`` (a
display for a topic of a type the view draws), ``{"flow": true}`` and ``{"ack": N}`` (flow
control: ``FlowTab``). Anything else is ignored.
"""

from __future__ import annotations

import asyncio
import contextlib
import functools
import json
from pathlib import Path
from typing import Any

from aiohttp import WSMsgType, web

from ros_tutorials_web.guard import Guard
from ros_tutorials_web.hub import Hub, Payload, Tab
from rviz2.scene import Scene

STATIC = Path(__file__).resolve().parent / "static"
MAX_NAME = 256  # characters of a frame or topic name a page may send
MESH_TYPES = {".stl": "model/stl", ".dae": "model/vnd.collada+xml"}
IN_FLIGHT = 2  # bulk payloads sent to a page that asked for flow control, not yet drawn


class FlowTab(Tab):
    """A tab of the hub, with flow control for the pages that ask for it.

    A page that says ``{"flow": true}`` acknowledges the binary frames (clouds, scans, maps,
    images) it has drawn (``{"ack": N}``); it is then sent at most IN_FLIGHT of them ahead of
    what it drew, so a page that draws slowly gets fresh data late, never a backlog of old
    data in the socket's buffers. Text payloads (tf, markers, config) are small and go at
    once."""

    def __init__(self, ws: web.WebSocketResponse) -> None:
        super().__init__(ws)
        self.flow = False
        self.in_flight = 0

    def acknowledge(self, count: int) -> None:
        self.in_flight = max(0, self.in_flight - count)
        self._ready.set()

    async def send(self) -> None:
        while not self.ws.closed:
            await self._ready.wait()
            self._ready.clear()
            held = self.flow and self.in_flight >= IN_FLIGHT
            for slot in list(self._pending):
                payload = self._pending[slot]
                if isinstance(payload, bytes) and held:
                    continue  # waits, replaced by a newer one meanwhile, until the page drew
                del self._pending[slot]
                if isinstance(payload, bytes):
                    self.in_flight += 1
                    held = self.flow and self.in_flight >= IN_FLIGHT
                    await self.ws.send_bytes(payload)
                else:
                    await self.ws.send_str(payload)


def deliver(hub: Hub, stream: str, payload: Payload) -> None:
    """A payload of the scene (on the event loop): kept for tabs to come, sent to every tab."""
    if stream not in hub.always:  # a display added since: every tab gets it too
        hub.always.add(stream)
        for tab in hub.tabs:
            hub.want(tab, stream)
    hub.offer(stream, payload)


def ask(scene: Scene, asked: Any) -> None:
    """What a page asks for, handed to the ROS thread; anything malformed is ignored."""
    if not isinstance(asked, dict):
        return
    if isinstance(asked.get("fixed"), str) and len(asked["fixed"]) <= MAX_NAME:
        scene.request(lambda: scene.set_fixed(asked["fixed"]))
    enable = asked.get("enable")
    if (
        isinstance(enable, list)
        and len(enable) == 2
        and isinstance(enable[0], int)
        and isinstance(enable[1], bool)
    ):
        scene.request(lambda: scene.set_enabled(enable[0], enable[1]))
    topic = asked.get("add")
    if isinstance(topic, str) and topic.startswith("/") and len(topic) <= MAX_NAME:
        scene.request(lambda: scene.add_for_topic(topic))


def make_app(hub: Hub, scene: Scene, door: Guard) -> web.Application:
    async def page(_request: web.Request) -> web.FileResponse:
        return web.FileResponse(STATIC / "rviz.html")

    async def mesh(request: web.Request) -> web.StreamResponse:
        try:
            number, index = int(request.match_info["display"]), int(request.match_info["index"])
        except ValueError:
            raise web.HTTPNotFound() from None
        path = scene.mesh_file(number, index)
        if path is None or path.name != request.match_info["name"]:
            raise web.HTTPNotFound(text="404: not a mesh of the current robot model\n")
        kind = MESH_TYPES.get(path.suffix.lower(), "application/octet-stream")
        return web.FileResponse(path, headers={"Content-Type": kind})

    async def websocket(request: web.Request) -> web.WebSocketResponse:
        ws = web.WebSocketResponse(heartbeat=20, max_msg_size=64 * 1024)
        await ws.prepare(request)
        tab = FlowTab(ws)
        hub.add(tab, list(hub.always))
        scene.request(functools.partial(scene.set_viewers, len(hub.tabs)))
        sender = asyncio.create_task(tab.send())

        def sent(task: asyncio.Task) -> None:  # a tab whose sending failed is closed
            if not task.cancelled() and task.exception() is not None:
                hub.loop.create_task(ws.close())

        sender.add_done_callback(sent)
        try:
            async for message in ws:
                if message.type != WSMsgType.TEXT:
                    continue
                with contextlib.suppress(ValueError):
                    asked = json.loads(message.data)
                    if isinstance(asked, dict) and asked.get("flow") is True:
                        tab.flow = True
                    if isinstance(asked, dict) and type(asked.get("ack")) is int:
                        tab.acknowledge(asked["ack"])
                    ask(scene, asked)
        finally:
            sender.cancel()
            hub.remove(tab)
            scene.request(functools.partial(scene.set_viewers, len(hub.tabs)))
            with contextlib.suppress(asyncio.CancelledError, ConnectionError):
                await sender
        return ws

    app = web.Application(middlewares=[door.middleware(scene.get_logger().warning)])
    app.on_shutdown.append(hub.close)
    app.router.add_get("/", page)
    app.router.add_get("/ws", websocket)
    app.router.add_get("/mesh/{display}/{index}/{name}", mesh)
    app.router.add_static("/static/", STATIC)
    return app
