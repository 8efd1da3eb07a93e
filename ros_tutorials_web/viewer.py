"""viewer: the running ROS system in a browser, for machines where no window can open.

This module is the viewer's routes and what its streams carry; guard.py is who may look,
hub.py passes the ROS side's news to the tabs, server.py runs the server beside the node,
watch.py is the ROS side (frames.py for tf).

    ros2 run ros_tutorials_web viewer              # http://127.0.0.1:8080/ (or a free port)
    ros2 run ros_tutorials_web viewer --port 9000  # exactly this port
    ros2 run ros_tutorials_web viewer --host 0.0.0.0   # reachable from other machines too
    ros2 run ros_tutorials_web viewer --allow-origin https://8080-abc.example.dev  # a proxy

One page shows, live: every turtlesim's canvas (its ~/_canvas/compressed topic, any
sensor_msgs/msg/CompressedImage topic in fact), the graph as rqt_graph draws it, the /rosout
log with level and node filters, any topic's newest message with a plot of one of its
numbers over time, and the tf2 frames: their tree, and each frame's axes drawn on turtlesim's
canvas (fixed frame ``world``) or on a grid. The viewer is an ordinary ROS 2 node
(``web_viewer``, watch.py); its own page only subscribes. The same server serves rqt's
plugins at ``/rqt`` (rqt.py: call, publish, set parameters and logger levels, plot, bag),
which the ``rqt`` commands open (commands.py).

The web side is aiohttp (HTTP and WebSockets on asyncio); the page is static files in
static/. Each browser tab gets, per stream, only the newest value it has not sent yet: a
slow or stalled tab misses frames, it never makes the viewer queue them.

Who may look (guard.py): the viewer prints a link with a token made for this run
(``/?token=...``); opening it sets a cookie for this host and port, and every request but
the page's own files needs the token; a request whose ``Host`` or ``Origin`` is not the
viewer's own is refused with a 403 and the reason. ``--allow-origin`` names a cloud
editor's forwarded port; ``--host 0.0.0.0`` (or ``::``) listens on every address.

HTTP: ``/`` the page, ``/rqt`` rqt's, ``/static/...`` their files, ``/ws`` the WebSocket,
``/api/graph.svg`` the graph picture, ``/api/topics`` topics and types (JSON),
``/api/log`` the newest /rosout entries (JSON).

WebSocket, server to browser: text frames are JSON objects with a ``type``: ``graph``
(``svg``, ``topics``: the visible ones and their types, ``pictures``: the picture
topics), ``log`` (``entries``: time, level, node, msg), ``topic`` (``topic``,
``type_name``, ``count``, ``yaml``, ``numbers``: each numeric field by its dotted path),
``tf`` (``fixed``: the frame the poses are in, ``total``, ``capped``, ``frames``: each with
``name``, ``parent``, ``broadcaster``, ``rate``, ``age``, ``static``, ``pose``: ``xyz``,
``q``, ``yaw``, ``x_axis``, ``y_axis``, or ``error``; frames.py);
binary frames are pictures: a 4-byte big-endian length, that many bytes of JSON (``topic``,
``mime``, ``stamp``, ``count``), then the image file's bytes. Browser to server: JSON
``{"watch": TOPIC}`` (or ``null``) chooses the topic whose messages this tab gets;
``{"tf": {"fixed": FRAME}}`` (``""``: the viewer chooses, ``world`` if there is one) asks for
the frames, ``{"tf": null}`` stops them; rqt's messages (``publish``, ``plot``, ``play``) are
in rqt.py.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import functools
import json
import math
import struct
import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from aiohttp import web
from rclpy.serialization import deserialize_message

from ros2cmd.messages import message_to_ordered, message_to_yaml
from ros_tutorials_common.ros import user_args
from ros_tutorials_common.shutdown import program_main
from ros_tutorials_web import guard, server
from ros_tutorials_web.frames import AUTO, MAX_NAME
from ros_tutorials_web.guard import Guard
from ros_tutorials_web.hub import Hub, Tab
from ros_tutorials_web.ros_calls import Ros
from ros_tutorials_web.rqt import Tools
from ros_tutorials_web.watch import Feed, LogFeed, Watcher

STATIC = Path(__file__).resolve().parent / "static"
STREAM_HZ = 30  # the most messages a second passed on per topic or picture stream
TRUNCATE = 64  # strings and arrays in a topic's message, as `ros2 topic echo` shortens them
YAML_LIMIT = 20000  # characters of one message's text
PLOT_SAMPLES = 1000  # messages of one topic in one plot payload (the newest)
MIME = {"png": "image/png", "jpeg": "image/jpeg", "jpg": "image/jpeg"}
# What a tab wants from the moment it opens (hub keys); "topic:NAME" and "tf:FRAME" on demand.
GRAPH, LOG, PICTURES = "graph", "log", "pictures"


def parse_args(argv: Sequence[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="viewer", description="The running ROS system in a browser: turtlesim, graph, log, tf"
    )
    guard.add_arguments(parser)
    return parser.parse_args(argv)


def numbers(data: dict[str, Any], prefix: str = "") -> dict[str, float | None]:
    """Every numeric field of a message (as plain data) by its dotted path; arrays left out,
    NaN and infinities as None (JSON has no word for them)."""
    found: dict[str, float | None] = {}
    for name, value in data.items():
        path = prefix + name
        if isinstance(value, dict):
            found.update(numbers(value, path + "."))
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            found[path] = value if math.isfinite(value) else None
    return found


def picture_frame(header: dict[str, Any], image: bytes) -> bytes:
    """A binary WebSocket frame: length of the JSON header, the header, the image file."""
    encoded = json.dumps(header).encode()
    return struct.pack("!I", len(encoded)) + encoded + image


class Streams:
    """What the viewer's node hands over, made into the payloads the hub passes on (on the
    event loop; the node's callbacks hand over with Hub.from_ros)."""

    def __init__(self, hub: Hub) -> None:
        self.hub = hub
        self.graph_svg = ""
        self.topic_types: dict[str, list[str]] = {}
        self._sent_at: dict[str, float] = {}

    # Called on the ROS thread: hand over, nothing more.
    def graph_from_ros(self, svg: str, topics: dict[str, list[str]], pictures: list[str]) -> None:
        self.hub.from_ros(self._graph, svg, topics, pictures)

    def feed_from_ros(self, feed: Feed) -> None:
        self.hub.from_ros(self._feed, feed)

    def log_from_ros(self, feed: LogFeed) -> None:
        self.hub.from_ros(lambda: self.hub.extend(LOG, feed.take()))

    def tf_from_ros(self, fixed: str, payload: str) -> None:
        self.hub.from_ros(self.hub.offer, "tf:" + fixed, payload, "tf")

    # On the event loop.
    def _graph(self, svg: str, topics: dict[str, list[str]], pictures: list[str]) -> None:
        self.graph_svg, self.topic_types = svg, topics
        payload = {"type": "graph", "svg": svg, "topics": topics, "pictures": pictures}
        self.hub.offer(GRAPH, json.dumps(payload))
        for slot in list(self.hub.kept.get(PICTURES, {})):
            if slot.removeprefix("picture:") not in pictures:  # gone: forget its frame
                self.hub.forget(PICTURES, slot)

    def _feed(self, feed: Feed) -> None:
        # At most STREAM_HZ a second per stream: a faster topic is sampled (its newest wins).
        picture = feed.type_name.endswith("CompressedImage")
        key = ("picture:" if picture else "topic:") + feed.topic
        wait = self._sent_at.get(key, -math.inf) + 1 / STREAM_HZ - self.hub.loop.time()
        if wait > 0:
            self.hub.loop.call_later(wait, self._feed, feed)
            return
        data = feed.take()
        history = feed.take_history()
        if data is None:
            return
        self._sent_at[key] = self.hub.loop.time()
        try:
            msg = deserialize_message(data, feed.message_class)
        except Exception:  # not what its type says (a publisher of another build): skipped
            return
        if picture:
            self._picture(feed, msg)
        else:
            self._topic(feed, msg, history)

    def _picture(self, feed: Feed, msg: Any) -> None:
        kind = next((MIME[w] for w in msg.format.replace(";", " ").split() if w in MIME), None)
        if kind is None:
            return  # a format a browser cannot show by itself
        header = {
            "topic": feed.topic,
            "mime": kind,
            "stamp": msg.header.stamp.sec + msg.header.stamp.nanosec / 1e9,
            "count": feed.count,
        }
        self.hub.offer(PICTURES, picture_frame(header, bytes(msg.data)), "picture:" + feed.topic)

    def _topic(self, feed: Feed, msg: Any, history: list[tuple[float, bytes]]) -> None:
        yaml_text = message_to_yaml(msg, truncate_length=TRUNCATE)
        payload = {
            "type": "topic",
            "topic": feed.topic,
            "type_name": feed.type_name,
            "count": feed.count,
            "yaml": yaml_text[:YAML_LIMIT],
            "numbers": numbers(message_to_ordered(msg, truncate_length=TRUNCATE)),
        }
        text = json.dumps(payload)
        self.hub.offer("topic:" + feed.topic, text, "topic")
        if not self.hub.wanted("plot:" + feed.topic):
            return
        # A plot gets every message since the last payload (a 100 Hz topic is not sampled).
        payload["time"] = time.time()
        payload["samples"] = self._samples(feed, history[-PLOT_SAMPLES:])
        self.hub.offer("plot:" + feed.topic, json.dumps(payload), "plot:" + feed.topic)

    @staticmethod
    def _samples(feed: Feed, history: list[tuple[float, bytes]]) -> list[list[Any]]:
        """[time it came, its numbers] of each message."""
        samples = []
        for came, data in history:
            try:
                msg = deserialize_message(data, feed.message_class)
            except Exception:  # not what its type says: skipped
                continue
            samples.append([came, numbers(message_to_ordered(msg, truncate_length=TRUNCATE))])
        return samples


def start(watcher: Watcher, key: str) -> None:
    """The first tab wants ``key`` (on the ROS thread)."""
    kind, _, name = key.partition(":")
    if kind == PICTURES:
        watcher.set_viewers(1)
    elif kind in ("topic", "plot"):
        watcher.watch(name, 1)
    elif kind == "tf":
        watcher.frames.want(name, 1)


def stop(watcher: Watcher, key: str) -> None:
    """The last tab that wanted ``key`` has dropped it, or gone (on the ROS thread)."""
    kind, _, name = key.partition(":")
    if kind == PICTURES:
        watcher.set_viewers(0)
    elif kind in ("topic", "plot"):
        watcher.watch(name, -1)
    elif kind == "tf":
        watcher.frames.want(name, -1)


def switch(hub: Hub, tab: Tab, prefix: str, name: str | None) -> None:
    """The tab wants ``prefix + name`` instead of what it wanted of that kind (None: none)."""
    for key in [k for k in tab.wants if k.startswith(prefix)]:
        if name is None or key != prefix + name:
            hub.drop(tab, key)
    if name is not None:
        hub.want(tab, prefix + name)


def asked(hub: Hub, tools: Tools, tab: Tab, text: str) -> Any:
    """A tab's message: ``{"watch": "/topic" or null}``, ``{"tf": {"fixed": FRAME} or
    null}``, or one of the rqt tools' (rqt.py; an awaitable to run as the tab's task);
    anything else is ignored (a tab's bug, not ours)."""
    try:
        message = json.loads(text)
    except ValueError:
        return None
    if not isinstance(message, dict):
        return None
    with contextlib.suppress(TypeError, AttributeError, KeyError):
        if "tf" in message:
            fixed = None if message["tf"] is None else message["tf"].get("fixed") or AUTO
            if fixed is None or (isinstance(fixed, str) and len(fixed) <= MAX_NAME):
                switch(hub, tab, "tf:", fixed)
            return None
        if "watch" in message:
            topic = message["watch"]
            if topic is None or (isinstance(topic, str) and topic.startswith("/")):
                switch(hub, tab, "topic:", topic)
            return None
        return tools.asked(tab, message)
    return None


def make_app(
    hub: Hub, streams: Streams, tools: Tools, door: Guard, say: Callable[[str], None]
) -> web.Application:
    async def page(_request: web.Request) -> web.FileResponse:
        return web.FileResponse(STATIC / "index.html")

    async def graph_svg(_request: web.Request) -> web.Response:
        return web.Response(text=streams.graph_svg, content_type="image/svg+xml")

    async def topics(_request: web.Request) -> web.Response:
        return web.json_response(streams.topic_types)

    async def log(_request: web.Request) -> web.Response:
        return web.json_response(list(hub.lists.get(LOG, [])))

    async def websocket(request: web.Request) -> web.WebSocketResponse:
        ws = web.WebSocketResponse(heartbeat=20, max_msg_size=64 * 1024)
        await ws.prepare(request)
        await hub.session(
            ws, (GRAPH, LOG, PICTURES), lambda tab, text: asked(hub, tools, tab, text)
        )
        return ws

    app = web.Application(middlewares=[door.middleware(say)])
    app.on_shutdown.append(hub.close)
    app.router.add_get("/", page)
    app.router.add_get("/ws", websocket)
    app.router.add_get("/api/graph.svg", graph_svg)
    app.router.add_get("/api/topics", topics)
    app.router.add_get("/api/log", log)
    tools.add_routes(app, door)
    app.router.add_static("/static/", STATIC)
    return app


@program_main
def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    return serve(argv, parse_args(user_args(argv)))


def serve(
    argv: Sequence[str],
    args: argparse.Namespace,
    path: str = "/",
    node_name: str = "web_viewer",
    on_listen: Callable[[str], None] | None = None,
) -> int:
    """Serve the viewer's pages (its own at ``/``, rqt's at ``/rqt``) with the options of
    guard.add_arguments; the greeting's link opens ``path``; on_listen(link) is called once
    the server listens (the rqt commands open a browser window with it)."""
    sock = guard.listen(args.host, args.port)  # before ROS starts: a taken port is one line
    door = Guard.for_socket(sock, args.host, args.allow_origins)

    def make(loop: asyncio.AbstractEventLoop) -> tuple[Watcher, web.Application]:
        hub = Hub(loop, always=(GRAPH, LOG))
        streams = Streams(hub)
        watcher = Watcher(
            streams.graph_from_ros, streams.feed_from_ros, streams.log_from_ros,
            streams.tf_from_ros, name=node_name,
        )  # fmt: skip
        hub.ros = watcher.request
        hub.start = functools.partial(start, watcher)
        hub.stop = functools.partial(stop, watcher)
        tools = Tools(Ros(watcher, watcher.request), hub)
        app = make_app(hub, streams, tools, door, watcher.get_logger().warning)
        if on_listen is not None:
            address, port = sock.getsockname()[:2]
            local = "127.0.0.1" if address in guard.WILDCARDS else address
            app.on_startup.append(
                lambda _app: loop.run_in_executor(
                    None, on_listen, guard.link(local, port, door.token, path)
                )
            )
        return watcher, app

    return server.run(argv, sock, door, make, exposed=guard.EXPOSED_TOOLS, path=path)


if __name__ == "__main__":
    sys.exit(main())
