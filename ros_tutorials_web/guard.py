"""The guard: who may talk to a local web server of this project (the viewer, and any other
tool's page: a 3D view, a sliders page, a server in another process).

As Jupyter and VS Code's servers do, every request passes three checks:

- **Host**: a request whose ``Host`` is not a name the server serves is refused (DNS
  rebinding: a web site whose name resolves to 127.0.0.1). Listening on every address
  (``--host 0.0.0.0`` or ``::``), any ``Host`` is accepted; the token still guards.
- **Origin**: a request whose ``Origin`` is not the server's own page is refused (any web
  site the learner visits can open a WebSocket to 127.0.0.1). A cloud editor's forwarded
  port shows the page under another origin: ``--allow-origin ORIGIN`` names it.
- **Token**: made for this run; the printed link carries it (``/?token=...``); opening the
  link sets a cookie for this host and port (HttpOnly, SameSite=Strict), and every request
  but the page's own files (``/static/...``) needs it: the cookie, ``?token=``, or
  ``Authorization: token ...``.

A refused request gets a 403 with the reason; the server logs each kind of refusal once.
Servers listen on 127.0.0.1 unless the user asks for another address (``--host``).

Using it for another tool's server (the routes are the tool's own; viewer.py is an example)::

    from ros_tutorials_web import guard

    parser = argparse.ArgumentParser(prog="mytool")
    guard.add_arguments(parser)                      # --port, --host, --allow-origin
    args = parser.parse_args(argv)
    sock = guard.listen(args.host, args.port)        # one line and exit 1 when it cannot
    door = guard.Guard.for_socket(sock, args.host, args.allow_origins)
    app = web.Application(middlewares=[door.middleware(logger.warning)])
    app.router.add_get("/", page)                    # behind the guard: needs the token
    app.router.add_get("/ws", stream)                # a WebSocket: Origin and token checked
    app.router.add_post("/api/call", door.writes(call))  # a writing route, see below
    app.router.add_static("/static/", STATIC)        # the page's files: no token needed
    print(guard.greeting(sock, door)[0])             # "Open http://127.0.0.1:P/?token=T ..."

(server.py runs such an app beside a ROS node, with Ctrl-C and SIGTERM handled.)

**Writing routes** (call a service, publish, set a parameter) act only for a page that
passed the guard: wrap the handler in ``Guard.writes``. On top of the token it requires a
POST whose body is JSON (``Content-Type: application/json``: a plain HTML form of another
site cannot send one, and a script of another site must ask first, which the server does
not answer) and an ``Origin`` header that is the server's own page (every browser sends one
with such a request). A WebSocket message that writes needs nothing more: the WebSocket's
Origin and token were checked when it opened.
"""

from __future__ import annotations

import argparse
import errno
import hmac
import ipaddress
import secrets
import socket
import urllib.parse
from collections.abc import Awaitable, Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

from aiohttp import web

DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 8080  # when free; else any free port (a port given with --port must be free)
WILDCARDS = ("0.0.0.0", "::")  # every address of the machine
LOOPBACK_NAMES = ("localhost", "127.0.0.1", "::1")
EXPOSED_TOOLS = (
    "watch the graph, /rosout and every topic, and call services, publish and set parameters "
    "with the rqt tools"
)

Handler = Callable[[web.Request], Awaitable[web.StreamResponse]]


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


def add_arguments(parser: argparse.ArgumentParser, default_port: int = DEFAULT_PORT) -> None:
    """--port, --host and --allow-origin, as every server of this project takes them."""
    parser.add_argument(
        "--port",
        type=port_number,
        help=f"the port to listen on (default {default_port}, or a free one if it is taken; "
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


def listen(host: str, port: int | None, default_port: int = DEFAULT_PORT) -> socket.socket:
    """The listening socket, or SystemExit with one line saying why there is none. With no
    port given, ``default_port`` if free, else any free port."""
    wanted = default_port if port is None else port
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


def link(host: str, port: int, token: str, path: str = "/") -> str:
    """The address a browser opens: the page at ``path`` (``/rqt#plot``: a fragment kept
    after the query), with this run's token."""
    where = f"[{host}]" if ":" in host else host
    page, hash_, fragment = path.partition("#")
    return f"http://{where}:{port}{page}?token={token}{hash_}{fragment}"


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
    def for_socket(
        cls, sock: socket.socket, host: str, origins: Sequence[str], token: str | None = None
    ) -> Guard:
        """The guard of a server on ``sock`` (listening on ``host`` as the user spelled it),
        with ``token`` if given (a server of another process may share a first one's), else a
        token made now."""
        address, port = sock.getsockname()[:2]
        if address in WILDCARDS:
            hosts = None
        else:
            hosts = {*LOOPBACK_NAMES, address.lower(), host.lower()}
            hosts.update(urllib.parse.urlsplit(o).hostname or "" for o in origins)
        return cls(
            token or secrets.token_urlsafe(24), f"ros_viewer_token_{port}", hosts, set(origins)
        )

    def refusal(self, request: web.Request) -> tuple[str, str] | None:
        """(kind, reason) when the request is refused, None when it may pass."""
        host = request.headers.get("Host", "")
        name = host_name(host)
        if not name or (self.hosts is not None and name not in self.hosts):
            return "host", f"Host {host[:100]!r} is not a name this viewer serves"
        page = request.headers.get("Origin")
        if page is not None and not self.own_page(request, page):
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

    def own_page(self, request: web.Request, page: str) -> bool:
        """Whether an Origin header names this server's own page (or an allowed proxy's)."""
        host = request.headers.get("Host", "").lower()
        return page.lower() in {f"http://{host}", f"https://{host}"} | self.origins

    def given_token(self, request: web.Request) -> str:
        words = request.headers.get("Authorization", "").split()
        if len(words) == 2 and words[0].lower() == "token":
            return words[1]
        return request.query.get("token") or request.cookies.get(self.cookie, "")

    def middleware(self, say: Callable[[str], None]) -> Any:
        """The aiohttp middleware that refuses what the guard refuses (``say`` logs each kind
        of refusal once) and sets the token's cookie when a page is opened with ?token=."""

        @web.middleware
        async def check(request: web.Request, handler: Handler) -> web.StreamResponse:
            refused = self.refusal(request)
            if refused is not None:
                kind, reason = refused
                if kind not in self.told:  # once per kind: a page retrying is not a flood
                    self.told.add(kind)
                    say(f"Refused {request.method} {request.path}: {reason}")
                return web.Response(status=403, text=f"403 Forbidden: {reason}\n")
            response = await handler(request)
            if request.query.get("token") == self.token and request.method == "GET":
                # A page was opened from the link: its WebSockets, fetches and reloads carry
                # the cookie.
                response.set_cookie(self.cookie, self.token, httponly=True, samesite="Strict")
            return response

        return check

    def writes(self, handler: Handler) -> Handler:
        """A writing route's handler (call, publish, set), run only for a POST of JSON from
        this server's own page; anything else is a 403 with the reason, and nothing is done.
        The middleware has checked Host and token before."""

        async def checked(request: web.Request) -> web.StreamResponse:
            page = request.headers.get("Origin")
            if request.method != "POST":
                reason = "a writing request must be a POST"
            elif request.content_type != "application/json":
                reason = "a writing request must send JSON (Content-Type: application/json)"
            elif page is None or not self.own_page(request, page):
                reason = "a writing request must come from this viewer's page (its Origin)"
            else:
                return await handler(request)
            return web.Response(status=403, text=f"403 Forbidden: {reason}\n")

        return checked


def greeting(
    sock: socket.socket,
    guard: Guard,
    exposed: str = EXPOSED_TOOLS,
    path: str = "/",
) -> list[str]:
    """What a server says when it listens: the link to ``path``, and a warning when other
    machines can reach it (``exposed``: what anyone with the link could then do)."""
    address, port = sock.getsockname()[:2]
    if address in WILDCARDS:
        local = link("127.0.0.1" if address == "0.0.0.0" else "::1", port, guard.token, path)
        others = link(socket.gethostname(), port, guard.token, path)
        lines = [f"Open {local} in a browser (Ctrl-C to stop); from other machines {others}"]
    else:
        lines = [f"Open {link(address, port, guard.token, path)} in a browser (Ctrl-C to stop)"]
    if not is_loopback(address):
        lines.append(
            f"Listening on {address}, not only on this machine: anyone on the network who has "
            f"the link can {exposed}"
        )
    return lines
