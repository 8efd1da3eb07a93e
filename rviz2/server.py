"""rviz2's web side: the 3D view's page, its files (three.js among them), its WebSocket and the
robot model's mesh files, behind the web viewer's guard (ros_tutorials_web: a token made for
this run, and the Host and Origin checks) on 127.0.0.1 unless asked otherwise.

HTTP: ``/`` the page (rviz.html), ``/static/...`` its files, ``/ws`` the WebSocket,
``/mesh/N/I/NAME`` mesh I of display N's robot model (only a file the current model names).

WebSocket, server to browser: the scene's streams (scene.py): ``config``, ``tf`` and one per
display, as JSON text or, with bulk data, binary frames (a 4-byte big-endian length, that many
bytes of JSON, the data). Each tab gets the newest payload of each stream that it has not got
yet: a slow tab misses updates, the server queues none. Browser to server, JSON:
``{"fixed": FRAME}`` (``""``: the view chooses), ``{"enable": [N, true|false]}``,
``{"add": TOPIC}`` (a display for a topic of a type the view draws), ``{"flow": true}`` and
``{"ack": N}`` (flow control: ``Tab``). Anything else is ignored.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

from aiohttp import WSMsgType, web
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor

from ros_tutorials_web.viewer import Guard
from rviz2.scene import Scene

STATIC = Path(__file__).resolve().parent / "static"
MAX_NAME = 256  # characters of a frame or topic name a page may send
MESH_TYPES = {".stl": "model/stl", ".dae": "model/vnd.collada+xml"}
IN_FLIGHT = 2  # bulk payloads sent to a page that asked for flow control, not yet drawn


class Tab:
    """One page's WebSocket: per stream, the newest payload not sent yet.

    A page that says ``{"flow": true}`` acknowledges the binary frames (clouds, scans, maps,
    images) it has drawn (``{"ack": N}``); it is then sent at most IN_FLIGHT of them ahead of
    what it drew, so a page that draws slowly gets fresh data late, never a backlog of old
    data in the socket's buffers. Text payloads (tf, markers, config) are small and go at
    once."""

    def __init__(self, ws: web.WebSocketResponse) -> None:
        self.ws = ws
        self.flow = False
        self.in_flight = 0
        self._pending: dict[str, str | bytes] = {}
        self._ready = asyncio.Event()

    def offer(self, stream: str, payload: str | bytes) -> None:
        self._pending[stream] = payload  # replaces what the page has not taken yet
        self._ready.set()

    def acknowledge(self, count: int) -> None:
        self.in_flight = max(0, self.in_flight - count)
        self._ready.set()

    async def send(self) -> None:
        while not self.ws.closed:
            await self._ready.wait()
            self._ready.clear()
            held = self.flow and self.in_flight >= IN_FLIGHT
            for stream in list(self._pending):
                payload = self._pending[stream]
                if isinstance(payload, bytes) and held:
                    continue  # waits, replaced by a newer one meanwhile, until the page drew
                del self._pending[stream]
                if isinstance(payload, bytes):
                    self.in_flight += 1
                    held = self.flow and self.in_flight >= IN_FLIGHT
                    await self.ws.send_bytes(payload)
                else:
                    await self.ws.send_str(payload)


class Hub:
    """The event loop's side: the newest payload of each stream, offered to every tab."""

    def __init__(self, loop: asyncio.AbstractEventLoop) -> None:
        self.loop = loop
        self.tabs: set[Tab] = set()
        self.newest: dict[str, str | bytes] = {}

    def from_ros(self, stream: str, payload: str | bytes) -> None:
        """The scene's handoff (ROS thread)."""
        self.loop.call_soon_threadsafe(self._offer, stream, payload)

    def _offer(self, stream: str, payload: str | bytes) -> None:
        self.newest[stream] = payload
        for tab in self.tabs:
            tab.offer(stream, payload)

    def add(self, tab: Tab) -> None:
        self.tabs.add(tab)
        for stream, payload in self.newest.items():
            tab.offer(stream, payload)


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


def make_app(hub: Hub, scene: Scene, guard: Guard, say: Callable[[str], None]) -> web.Application:
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
        tab = Tab(ws)
        hub.add(tab)
        sender = asyncio.create_task(tab.send())
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
            hub.tabs.discard(tab)
            with contextlib.suppress(asyncio.CancelledError, ConnectionError):
                await sender
        return ws

    app = web.Application(middlewares=[guard.middleware(say)])
    app.router.add_get("/", page)
    app.router.add_get("/ws", websocket)
    app.router.add_get("/mesh/{display}/{index}/{name}", mesh)
    app.router.add_static("/static/", STATIC)
    return app


async def serve(
    sock: Any, guard: Guard, make_scene: Callable[[Callable], Scene], ready: Callable
) -> None:
    """Serve until Ctrl-C or SIGTERM, with the scene's node spinning in a thread of its own;
    ``ready(scene)`` once the page can be opened."""
    import signal

    loop = asyncio.get_running_loop()
    stop = asyncio.Event()
    for signum in (signal.SIGINT, signal.SIGTERM):
        loop.add_signal_handler(signum, stop.set)
    hub = Hub(loop)
    scene = make_scene(hub.from_ros)
    executor = SingleThreadedExecutor()
    executor.add_node(scene)
    spinning = threading.Event()
    spinning.set()

    def spin() -> None:
        with contextlib.suppress(ExternalShutdownException):
            while spinning.is_set():
                executor.spin_once(timeout_sec=0.2)

    thread = threading.Thread(target=spin, name="ros", daemon=True)
    thread.start()
    app = make_app(hub, scene, guard, scene.get_logger().warning)
    runner = web.AppRunner(app, handle_signals=False, access_log=None)
    await runner.setup()
    try:
        await web.SockSite(runner, sock, shutdown_timeout=1.0).start()
        ready(scene)
        await stop.wait()
    finally:
        for tab in list(hub.tabs):
            with contextlib.suppress(Exception):
                await tab.ws.close()
        await runner.cleanup()
        spinning.clear()
        scene.request(lambda: None)  # wakes the executor at once
        thread.join()
        executor.shutdown()
        scene.destroy_node()
