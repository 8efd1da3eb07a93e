"""viewer: the running ROS system in a browser, for machines where no window can open.

(About 600 lines: the web server's routes, its guard of who may look, and its streams, read
together; the ROS side is watch.py, and frames.py for tf.)

    ros2 run ros_tutorials_web viewer              # http://127.0.0.1:8080/ (or a free port)
    ros2 run ros_tutorials_web viewer --port 9000  # exactly this port
    ros2 run ros_tutorials_web viewer --host 0.0.0.0   # reachable from other machines too
    ros2 run ros_tutorials_web viewer --allow-origin https://8080-abc.example.dev  # a proxy

One page shows, live: every turtlesim's canvas (its ~/_canvas/compressed topic, any
sensor_msgs/msg/CompressedImage topic in fact), the graph as rqt_graph draws it, the /rosout
log with level and node filters, any topic's newest message with a plot of one of its
numbers over time, and the tf2 frames: their tree, and each frame's axes drawn on turtlesim's
canvas (fixed frame ``world``) or on a grid. The viewer is an ordinary ROS 2 node
(``web_viewer``, watch.py) and only subscribes: it changes nothing in the graph.

The web side is aiohttp (HTTP and WebSockets on asyncio); the page is static files in
static/. Each browser tab gets, per stream, only the newest value it has not sent yet: a
slow or stalled tab misses frames, it never makes the viewer queue them.

Who may look: the viewer prints a link with a token made for this run (``/?token=...``);
opening it sets a cookie for this host and port, and every request but the page's own files
needs the token (the cookie, ``?token=``, or ``Authorization: token ...``). As Jupyter and VS
Code's servers do, a request whose ``Host`` is not a name the viewer serves is refused (DNS
rebinding: a web site whose name resolves to 127.0.0.1), and so is one whose ``Origin`` is
not the viewer's own page (any web site the learner visits can open a WebSocket to
127.0.0.1): a 403 with the reason. A cloud editor's forwarded port shows the page under
another origin: ``--allow-origin`` names it. With ``--host 0.0.0.0`` (or ``::``) any ``Host``
is accepted, the token still guards.

HTTP: ``/`` the page, ``/static/...`` its files, ``/ws`` the WebSocket,
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
the frames, ``{"tf": null}`` stops them.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import errno
import hmac
import ipaddress
import json
import math
import secrets
import signal
import socket
import struct
import sys
import threading
import urllib.parse
from collections import deque
from collections.abc import Awaitable, Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import rclpy
from aiohttp import WSMsgType, web
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.serialization import deserialize_message
from rclpy.signals import SignalHandlerOptions

from ros2cmd.messages import message_to_ordered, message_to_yaml
from ros_tutorials_common.ros import init, user_args
from ros_tutorials_web.frames import AUTO, MAX_NAME
from ros_tutorials_web.watch import LOG_KEEP, Feed, LogFeed, Watcher

STATIC = Path(__file__).resolve().parent / "static"
DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 8080  # when free; else any free port (a port given with --port must be free)
STREAM_HZ = 30  # the most messages a second passed on per topic or picture stream
TRUNCATE = 64  # strings and arrays in a topic's message, as `ros2 topic echo` shortens them
YAML_LIMIT = 20000  # characters of one message's text
MIME = {"png": "image/png", "jpeg": "image/jpeg", "jpg": "image/jpeg"}


def port_number(text: str) -> int:
    """An argparse type: a TCP port, 0 (any free one) to 65535."""
    try:
        port = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a port number") from None
    if not 0 <= port <= 65535:
        raise argparse.ArgumentTypeError(f"{text} is not a port number (0 to 65535)")
    return port


def origin(text: str) -> str:
    """An argparse type: a web origin, scheme://host[:port], as a browser's Origin header
    spells it (lower case, no path)."""
    problem = f"{text!r} is not an origin: http(s)://host[:port], e.g. https://8080-x.example.dev"
    url = urllib.parse.urlsplit(text.strip())
    try:
        url.port  # noqa: B018 - raises ValueError for a port that is not a number
    except ValueError:
        raise argparse.ArgumentTypeError(problem) from None
    has_more = url.path not in ("", "/") or url.query or url.fragment or "@" in url.netloc
    if url.scheme not in ("http", "https") or not url.hostname or has_more:
        raise argparse.ArgumentTypeError(problem)
    return f"{url.scheme}://{url.netloc.lower()}"


def parse_args(argv: Sequence[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="viewer", description="The running ROS system in a browser: turtlesim, graph, log, tf"
    )
    parser.add_argument(
        "--port",
        type=port_number,
        help=f"the port to listen on (default {DEFAULT_PORT}, or a free one if it is taken; "
        "0: any free port)",
    )
    parser.add_argument(
        "--host",
        default=DEFAULT_HOST,
        help=f"the address to listen on (default {DEFAULT_HOST}: this machine only)",
    )
    parser.add_argument(
        "--allow-origin",
        action="append",
        default=[],
        type=origin,
        metavar="ORIGIN",
        dest="allow_origins",
        help="also accept the page shown from ORIGIN (a cloud editor's forwarded port, e.g. "
        "https://8080-abc.example.dev); may be given more than once",
    )
    return parser.parse_args(argv)


def listen(host: str, port: int | None) -> socket.socket:
    """The listening socket, or SystemExit with one line saying why there is none."""
    wanted = DEFAULT_PORT if port is None else port
    try:
        family, _, _, _, address = socket.getaddrinfo(
            host, wanted, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE
        )[0]
    except (socket.gaierror, UnicodeError) as error:
        raise SystemExit(f"error: cannot listen on {host!r}: {error}") from None
    try:
        return socket.create_server(address, family=family)
    except OSError as error:
        if error.errno == errno.EADDRINUSE and port is None:
            return listen(host, 0)  # the default is taken: any free port will do
        if error.errno == errno.EADDRINUSE:
            reason = "is in use by another program; choose another with --port (0: any free)"
        elif error.errno == errno.EACCES:
            reason = "needs root privileges (ports below 1024); choose one from 1024 up"
        elif error.errno == errno.EADDRNOTAVAIL:
            message = f"error: cannot listen on {host}: not an address of this machine"
            raise SystemExit(message) from None
        else:
            reason = f"cannot be used: {error.strerror}"
        raise SystemExit(f"error: port {wanted} on {host} {reason}") from None


WILDCARDS = ("0.0.0.0", "::")  # every address of the machine
LOOPBACK_NAMES = ("localhost", "127.0.0.1", "::1")


def link(host: str, port: int, token: str) -> str:
    """The address a browser opens: the page, with this run's token."""
    where = f"[{host}]" if ":" in host else host
    return f"http://{where}:{port}/?token={token}"


def is_loopback(address: str) -> bool:
    try:
        return ipaddress.ip_address(address).is_loopback
    except ValueError:
        return False


def host_name(header: str) -> str | None:
    """The name in a Host header (without its port, lower case), or None if it is not one."""
    try:
        return urllib.parse.urlsplit("//" + header).hostname
    except ValueError:
        return None


@dataclass
class Guard:
    """Who may look: the Host, Origin and token checks every request goes through."""

    token: str
    cookie: str  # the cookie's name: one per port (cookies do not tell ports apart)
    hosts: set[str] | None  # names accepted in Host; None: any (listening on every address)
    origins: set[str] = field(default_factory=set)  # pages of other origins allowed
    told: set[str] = field(default_factory=set)  # kinds of refusal logged once already

    @classmethod
    def for_socket(cls, sock: socket.socket, host: str, origins: Sequence[str]) -> Guard:
        address, port = sock.getsockname()[:2]
        if address in WILDCARDS:
            hosts = None
        else:
            hosts = {*LOOPBACK_NAMES, address.lower(), host.lower()}
            hosts.update(urllib.parse.urlsplit(o).hostname or "" for o in origins)
        token = secrets.token_urlsafe(24)
        return cls(token, f"ros_viewer_token_{port}", hosts, set(origins))

    def refusal(self, request: web.Request) -> tuple[str, str] | None:
        """(kind, reason) when the request is refused, None when it may pass."""
        host = request.headers.get("Host", "")
        name = host_name(host)
        if not name or (self.hosts is not None and name not in self.hosts):
            return "host", f"Host {host[:100]!r} is not a name this viewer serves"
        page = request.headers.get("Origin")
        if page is not None:
            own = {f"http://{host.lower()}", f"https://{host.lower()}"}
            if page.lower() not in own | self.origins:
                return "origin", (
                    f"Origin {page[:100]!r} is not this viewer's page (a proxy's page is allowed "
                    "with --allow-origin ORIGIN)"
                )
        if request.path.startswith("/static/") and "/.." not in request.path:
            return None  # the page's own files: nothing in them to hide
        # Header bytes that are not UTF-8 come as lone surrogates: compared as they came.
        given = self.given_token(request).encode("utf-8", "surrogateescape")
        if not hmac.compare_digest(given, self.token.encode()):
            return "token", "no valid token: open the link the viewer printed (with ?token=)"
        return None

    def given_token(self, request: web.Request) -> str:
        words = request.headers.get("Authorization", "").split()
        if len(words) == 2 and words[0].lower() == "token":
            return words[1]
        return request.query.get("token") or request.cookies.get(self.cookie, "")

    def middleware(self, say: Callable[[str], None]) -> Any:
        @web.middleware
        async def check(
            request: web.Request, handler: Callable[[web.Request], Awaitable[web.StreamResponse]]
        ) -> web.StreamResponse:
            refused = self.refusal(request)
            if refused is not None:
                kind, reason = refused
                if kind not in self.told:  # once per kind: a page retrying is not a flood
                    self.told.add(kind)
                    say(f"Refused {request.method} {request.path}: {reason}")
                return web.Response(status=403, text=f"403 Forbidden: {reason}\n")
            response = await handler(request)
            if request.query.get("token") == self.token and request.path == "/":
                # The link was opened: the page's WebSocket and reloads carry the cookie.
                response.set_cookie(self.cookie, self.token, httponly=True, samesite="Strict")
            return response

        return check


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


class Tab:
    """One browser tab's WebSocket: per stream, the newest payload not sent yet."""

    def __init__(self, ws: web.WebSocketResponse) -> None:
        self.ws = ws
        self.watching: str | None = None
        self.tf: str | None = None  # the fixed frame of the tf frames this tab gets (AUTO: any)
        self._pending: dict[str, str | bytes] = {}
        self._logs: deque[dict] = deque(maxlen=LOG_KEEP)
        self._ready = asyncio.Event()

    def offer(self, stream: str, payload: str | bytes) -> None:
        self._pending[stream] = payload  # replaces what a slow tab has not taken yet
        self._ready.set()

    def offer_logs(self, entries: list[dict]) -> None:
        self._logs.extend(entries)
        self._ready.set()

    async def send(self) -> None:
        """Send what is pending, as it comes, until the tab goes."""
        while not self.ws.closed:
            await self._ready.wait()
            self._ready.clear()
            if self._logs:
                entries = list(self._logs)
                self._logs.clear()
                await self.ws.send_str(json.dumps({"type": "log", "entries": entries}))
            while self._pending:
                payload = self._pending.pop(next(iter(self._pending)))
                if isinstance(payload, bytes):
                    await self.ws.send_bytes(payload)
                else:
                    await self.ws.send_str(payload)


class Hub:
    """The event loop's side: what the ROS thread hands over, passed on to the tabs."""

    def __init__(self, loop: asyncio.AbstractEventLoop) -> None:
        self.loop = loop
        self.tabs: set[Tab] = set()
        self.watcher: Watcher | None = None
        self.graph_svg = ""
        self.graph_payload: str | None = None
        self.topic_types: dict[str, list[str]] = {}
        self.log: deque[dict] = deque(maxlen=LOG_KEEP)
        self.pictures: dict[str, bytes] = {}  # topic -> its newest frame, for new tabs
        self.topic_payloads: dict[str, str] = {}
        self.tf_payloads: dict[str, str] = {}  # fixed frame -> the newest tf message
        self._sent_at: dict[str, float] = {}

    # Called on the ROS thread: hand over, nothing more.
    def graph_from_ros(self, svg: str, topics: dict[str, list[str]], pictures: list[str]) -> None:
        self.loop.call_soon_threadsafe(self._graph, svg, topics, pictures)

    def feed_from_ros(self, feed: Feed) -> None:
        self.loop.call_soon_threadsafe(self._feed, feed)

    def log_from_ros(self, feed: LogFeed) -> None:
        self.loop.call_soon_threadsafe(self._log, feed)

    def tf_from_ros(self, fixed: str, payload: str) -> None:
        self.loop.call_soon_threadsafe(self._tf, fixed, payload)

    # On the event loop.
    def _graph(self, svg: str, topics: dict[str, list[str]], pictures: list[str]) -> None:
        self.graph_svg, self.topic_types = svg, topics
        self.graph_payload = json.dumps(
            {"type": "graph", "svg": svg, "topics": topics, "pictures": pictures}
        )
        for tab in self.tabs:
            tab.offer("graph", self.graph_payload)
        for topic in [t for t in self.pictures if t not in pictures]:  # gone: forget its frame
            del self.pictures[topic]

    def _log(self, feed: LogFeed) -> None:
        entries = feed.take()
        self.log.extend(entries)
        for tab in self.tabs:
            tab.offer_logs(entries)

    def _tf(self, fixed: str, payload: str) -> None:
        if not any(tab.tf == fixed for tab in self.tabs):
            return  # the tabs that asked have gone meanwhile
        self.tf_payloads[fixed] = payload
        for tab in self.tabs:
            if tab.tf == fixed:
                tab.offer("tf", payload)

    def _feed(self, feed: Feed) -> None:
        # At most STREAM_HZ a second per stream: a faster topic is sampled (its newest wins).
        key = ("picture:" if feed.type_name.endswith("CompressedImage") else "topic:") + feed.topic
        wait = self._sent_at.get(key, -math.inf) + 1 / STREAM_HZ - self.loop.time()
        if wait > 0:
            self.loop.call_later(wait, self._feed, feed)
            return
        data = feed.take()
        if data is None:
            return
        self._sent_at[key] = self.loop.time()
        try:
            msg = deserialize_message(data, feed.message_class)
        except Exception:  # not what its type says (a publisher of another build): skipped
            return
        if key.startswith("picture:"):
            self._picture(feed, msg)
        else:
            self._topic(feed, msg)

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
        frame = self.pictures[feed.topic] = picture_frame(header, bytes(msg.data))
        for tab in self.tabs:
            tab.offer("picture:" + feed.topic, frame)

    def _topic(self, feed: Feed, msg: Any) -> None:
        text = message_to_yaml(msg, truncate_length=TRUNCATE)
        payload = json.dumps(
            {
                "type": "topic",
                "topic": feed.topic,
                "type_name": feed.type_name,
                "count": feed.count,
                "yaml": text[:YAML_LIMIT],
                "numbers": numbers(message_to_ordered(msg, truncate_length=TRUNCATE)),
            }
        )
        self.topic_payloads[feed.topic] = payload
        for tab in self.tabs:
            if tab.watching == feed.topic:
                tab.offer("topic", payload)

    # Tabs coming and going.
    def ros(self, change: Any, *args: Any) -> None:
        if self.watcher is not None:
            self.watcher.request(lambda: change(*args))

    def add(self, tab: Tab) -> None:
        self.tabs.add(tab)
        assert self.watcher is not None
        self.ros(self.watcher.set_viewers, len(self.tabs))
        if self.graph_payload is not None:
            tab.offer("graph", self.graph_payload)
        tab.offer_logs(list(self.log))
        for topic, frame in self.pictures.items():
            tab.offer("picture:" + topic, frame)

    def watch(self, tab: Tab, topic: str | None) -> None:
        assert self.watcher is not None
        old, tab.watching = tab.watching, topic
        if old is not None:
            self.ros(self.watcher.watch, old, -1)
            if not any(other.watching == old for other in self.tabs):
                self.topic_payloads.pop(old, None)  # unsubscribed: it would only get old
        if topic is not None:
            self.ros(self.watcher.watch, topic, 1)
            if topic in self.topic_payloads:
                tab.offer("topic", self.topic_payloads[topic])

    def show_tf(self, tab: Tab, fixed: str | None) -> None:
        """The tab gets the tf frames with poses in ``fixed`` (AUTO: the viewer chooses), or
        none (None)."""
        assert self.watcher is not None
        old, tab.tf = tab.tf, fixed
        if old == fixed:
            return
        if old is not None:
            self.ros(self.watcher.frames.want, old, -1)
            if not any(other.tf == old for other in self.tabs):
                self.tf_payloads.pop(old, None)
        if fixed is not None:
            self.ros(self.watcher.frames.want, fixed, 1)
            if fixed in self.tf_payloads:
                tab.offer("tf", self.tf_payloads[fixed])

    def remove(self, tab: Tab) -> None:
        self.watch(tab, None)
        self.show_tf(tab, None)
        self.tabs.discard(tab)
        assert self.watcher is not None
        self.ros(self.watcher.set_viewers, len(self.tabs))
        if not self.tabs:
            self.pictures.clear()  # not subscribed any more: these will be old


def make_app(hub: Hub, guard: Guard, say: Callable[[str], None]) -> web.Application:
    async def page(_request: web.Request) -> web.FileResponse:
        return web.FileResponse(STATIC / "index.html")

    async def graph_svg(_request: web.Request) -> web.Response:
        return web.Response(text=hub.graph_svg, content_type="image/svg+xml")

    async def topics(_request: web.Request) -> web.Response:
        return web.json_response(hub.topic_types)

    async def log(_request: web.Request) -> web.Response:
        return web.json_response(list(hub.log))

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
                # Anything but {"watch": "/topic" or null} or {"tf": {"fixed": "frame"} or
                # null} is ignored (a tab's bug, not ours).
                with contextlib.suppress(ValueError, TypeError, AttributeError, KeyError):
                    asked = json.loads(message.data)
                    if "tf" in asked:
                        fixed = None if asked["tf"] is None else asked["tf"].get("fixed") or AUTO
                        if fixed is None or (isinstance(fixed, str) and len(fixed) <= MAX_NAME):
                            hub.show_tf(tab, fixed)
                        continue
                    topic = asked["watch"]
                    if topic is None or (isinstance(topic, str) and topic.startswith("/")):
                        hub.watch(tab, topic)
        finally:
            sender.cancel()
            hub.remove(tab)
            with contextlib.suppress(asyncio.CancelledError, ConnectionError):
                await sender
        return ws

    app = web.Application(middlewares=[guard.middleware(say)])
    app.router.add_get("/", page)
    app.router.add_get("/ws", websocket)
    app.router.add_get("/api/graph.svg", graph_svg)
    app.router.add_get("/api/topics", topics)
    app.router.add_get("/api/log", log)
    app.router.add_static("/static/", STATIC)
    return app


def greeting(sock: socket.socket, guard: Guard) -> list[str]:
    """What the viewer says when it listens: the link, and a warning when other machines
    can reach it."""
    address, port = sock.getsockname()[:2]
    if address in WILDCARDS:
        local = link("127.0.0.1" if address == "0.0.0.0" else "::1", port, guard.token)
        others = link(socket.gethostname(), port, guard.token)
        lines = [f"Open {local} in a browser (Ctrl-C to stop); from other machines {others}"]
    else:
        lines = [f"Open {link(address, port, guard.token)} in a browser (Ctrl-C to stop)"]
    if not is_loopback(address):
        lines.append(
            f"Listening on {address}, not only on this machine: anyone on the network who has "
            "the link can watch the graph, /rosout and every topic (the viewer publishes nothing)"
        )
    return lines


async def serve(sock: socket.socket, guard: Guard) -> None:
    """Serve until Ctrl-C or SIGTERM, with the ROS node spinning in a thread of its own."""
    loop = asyncio.get_running_loop()
    stop = asyncio.Event()
    for signum in (signal.SIGINT, signal.SIGTERM):
        loop.add_signal_handler(signum, stop.set)
    hub = Hub(loop)
    watcher = hub.watcher = Watcher(
        hub.graph_from_ros, hub.feed_from_ros, hub.log_from_ros, hub.tf_from_ros
    )
    executor = SingleThreadedExecutor()
    executor.add_node(watcher)
    spinning = threading.Event()
    spinning.set()

    def spin() -> None:
        with contextlib.suppress(ExternalShutdownException):
            while spinning.is_set():
                executor.spin_once(timeout_sec=0.2)

    thread = threading.Thread(target=spin, name="ros", daemon=True)
    thread.start()
    logger = watcher.get_logger()
    app = make_app(hub, guard, logger.warning)
    runner = web.AppRunner(app, handle_signals=False, access_log=None)
    await runner.setup()
    try:
        await web.SockSite(runner, sock, shutdown_timeout=1.0).start()
        first, *warnings = greeting(sock, guard)
        logger.info(first)
        for line in warnings:
            logger.warning(line)
        await stop.wait()
    finally:
        for tab in list(hub.tabs):
            with contextlib.suppress(Exception):
                await tab.ws.close()
        await runner.cleanup()
        spinning.clear()
        watcher.request(lambda: None)  # wakes the executor at once
        thread.join()
        executor.shutdown()
        watcher.destroy_node()


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    args = parse_args(user_args(argv))
    sock = listen(args.host, args.port)  # before ROS starts: a taken port is one line
    guard = Guard.for_socket(sock, args.host, args.allow_origins)
    try:
        # Ctrl-C and SIGTERM stop the event loop, which then ends ROS in order.
        init(argv, signal_handler_options=SignalHandlerOptions.NO)
        asyncio.run(serve(sock, guard))
    except KeyboardInterrupt:  # pressed before the event loop took Ctrl-C over
        pass
    finally:
        sock.close()
        rclpy.try_shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
