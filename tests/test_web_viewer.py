"""The web viewer (`ros2 run ros_tutorials_web viewer`) against a real headless turtlesim:
its HTTP endpoints and its WebSocket protocol from Python (aiohttp's client), its bad input,
and the page itself in a headless browser where one is installed (Debian's chromium with
chromedriver, driven by selenium); skipped with the reason where there is none.
"""

from __future__ import annotations

import asyncio
import io
import json
import re
import socket
import struct
import time
import urllib.request
from collections.abc import Callable
from typing import Any

import aiohttp
import pygame
import pytest
from browser import chromium, text_of, until
from helpers import BIN, TIMEOUT, ok, run

from ros_tutorials_turtlesim.canvas import png_bytes
from ros_tutorials_turtlesim.simulation import DEFAULT_PEN
from ros_tutorials_web.guard import Guard, greeting

HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
CANVAS = "/turtlesim/_canvas/compressed"
LINK = r"Open (http://127\.0\.0\.1:\d+/\?token=[\w-]{32}) in a browser"
RELOADS = 25  # of the page, one after the other
DRIVE = ("{linear: {x: 2.0}, angular: {z: 1.8}}", "{linear: {x: 2.0}, angular: {z: -1.8}}")


def drive(twist: str = DRIVE[0]) -> None:
    """The learner's command: the turtle drives (and draws) for a second."""
    ok("ros2", "topic", "pub", "--once", "/turtle1/cmd_vel", "geometry_msgs/msg/Twist", twist)


def trail_pixels(png: bytes) -> int:
    """How many pixels of the picture have the pen's colour."""
    image = pygame.image.load(io.BytesIO(png), "canvas.png")
    raw = pygame.image.tobytes(image, "RGB")
    pen = bytes(DEFAULT_PEN)
    return sum(raw[i : i + 3] == pen for i in range(0, len(raw), 3))


def picture(data: bytes) -> tuple[dict[str, Any], bytes]:
    """A binary frame of the viewer: its JSON header and the image file."""
    (length,) = struct.unpack("!I", data[:4])
    return json.loads(data[4 : 4 + length]), data[4 + length :]


class Tab:
    """A WebSocket to the viewer, as a browser tab holds one; messages read on demand."""

    def __init__(self, ws: aiohttp.ClientWebSocketResponse) -> None:
        self.ws = ws

    async def until(self, found: Callable[[Any], Any], what: str, timeout: float = TIMEOUT):
        """Read messages (JSON dicts, or (header, image) for pictures) until found() gives
        something truthy; return it."""
        deadline = time.monotonic() + timeout
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                pytest.fail(f"{what}: not seen from the viewer within {timeout:.0f} s")
            try:
                message = await self.ws.receive(timeout=remaining)
            except asyncio.TimeoutError:
                continue
            if message.type == aiohttp.WSMsgType.BINARY:
                result = found(picture(message.data))
            elif message.type == aiohttp.WSMsgType.TEXT:
                result = found(json.loads(message.data))
            else:
                pytest.fail(f"{what}: the viewer closed the WebSocket ({message.type})")
            if result:
                return result


def at(link: str, path: str = "") -> str:
    """The viewer's PATH, with the token of the link it printed (http://HOST:PORT/?token=T)."""
    page, _, query = link.partition("?")
    return f"{page}{path}?{query}"


def with_tab(url: str, test: Callable[[Tab], Any]) -> Any:
    """Run the async test(tab) with a WebSocket open to the viewer."""

    async def session() -> Any:
        async with aiohttp.ClientSession() as client, client.ws_connect(at(url, "ws")) as ws:
            return await test(Tab(ws))

    return asyncio.run(session())


def canvas_frame(item: Any) -> tuple[dict, bytes] | None:
    return item if isinstance(item, tuple) and item[0]["topic"] == CANVAS else None


@pytest.fixture(scope="class")
def viewer(class_own_domain, class_node_process) -> str:
    """A headless turtlesim and the viewer (on a free port) in a domain of their own; the
    viewer's address, as it prints it."""
    sim = class_node_process(str(BIN / "ros2"), "run", "turtlesim", "turtlesim_node", env=HEADLESS)
    sim.wait_for_text("Spawning turtle [turtle1]")
    process = class_node_process(
        str(BIN / "ros2"), "run", "ros_tutorials_web", "viewer", "--port", "0"
    )
    line = process.wait_for_text("in a browser")[-1]
    found = re.search(LINK, line)
    assert found, line
    return found.group(1)


def test_canvas_png_is_exact() -> None:
    """turtlesim's own PNG writer (fast, lossless): another reader gets every pixel back."""
    surface = pygame.Surface((37, 23))
    surface.fill((69, 86, 255))
    pygame.draw.line(surface, DEFAULT_PEN, (0, 0), (36, 22), 3)
    surface.set_at((36, 0), (1, 2, 3))
    assert b"tEXt" not in png_bytes(surface)  # only a snapshot carries turtlesim's mark
    image = pygame.image.load(io.BytesIO(png_bytes(surface)), "canvas.png")
    assert image.get_size() == (37, 23)
    assert pygame.image.tobytes(image, "RGB") == pygame.image.tobytes(surface, "RGB")


class TestViewer:
    """One turtlesim and one viewer for the class; each test drives or asks, none stops them."""

    def test_page_and_endpoints(self, viewer: str) -> None:
        async def check() -> None:
            async with aiohttp.ClientSession() as client:
                async with client.get(viewer) as page:
                    assert page.status == 200
                    text = await page.text()
                    assert 'src="static/viewer.js"' in text and "http" not in text.split("-->")[1]
                for name in ("viewer.js", "viewer.css"):
                    async with client.get(at(viewer, "static/" + name)) as file:
                        assert file.status == 200
                deadline = time.monotonic() + TIMEOUT
                while True:  # the graph is looked at every second
                    async with client.get(at(viewer, "api/topics")) as answer:
                        topics = await answer.json()
                    if "/turtle1/pose" in topics or time.monotonic() > deadline:
                        break
                    await asyncio.sleep(0.2)
                assert topics["/turtle1/pose"] == ["turtlesim/msg/Pose"]
                assert CANVAS not in topics  # hidden, as `ros2 topic list` hides it
                async with client.get(at(viewer, "api/graph.svg")) as answer:
                    svg = await answer.text()
                    assert answer.content_type == "image/svg+xml"
                assert svg.startswith("<svg") and ">/turtlesim</text>" in svg
                assert "web_viewer" not in svg  # the viewer leaves itself out, as rqt_graph
                async with client.get(at(viewer, "api/log")) as answer:
                    log = await answer.json()
                assert any(e["msg"].startswith("Spawning turtle [turtle1]") for e in log)
                async with client.get(at(viewer, "no/such/page")) as answer:
                    assert answer.status == 404

        asyncio.run(check())

    def test_canvas_frames_follow_the_turtle(self, viewer: str) -> None:
        async def check(tab: Tab) -> None:
            header, first = await tab.until(canvas_frame, "a first canvas frame")
            assert header["mime"] == "image/png"
            assert pygame.image.load(io.BytesIO(first), "c.png").get_size() == (500, 500)
            before = trail_pixels(first)
            await asyncio.to_thread(drive)

            def more_trail(item: Any) -> Any:
                frame = canvas_frame(item)
                # Any new trail: a loaded machine runs fewer of turtlesim's steps a second.
                return frame if frame and trail_pixels(frame[1]) > before + 20 else None

            later, _ = await tab.until(more_trail, "a frame with the new trail")
            assert later["count"] > header["count"]
            assert later["stamp"] > header["stamp"]

        with_tab(viewer, check)

    def test_an_idle_canvas_is_sent_again(self, viewer: str) -> None:
        """Nothing drawn: turtlesim still sends its canvas again (about once a second), so a
        first frame lost as the reader joined is made good."""

        async def check(tab: Tab) -> None:
            header, _ = await tab.until(canvas_frame, "a first canvas frame")

            def next_frame(item: Any) -> Any:
                frame = canvas_frame(item)
                return frame if frame and frame[0]["count"] > header["count"] else None

            await tab.until(next_frame, "the idle canvas sent again")

        with_tab(viewer, check)

    def test_rosout_entries_arrive(self, viewer: str) -> None:
        def spawned(name: str) -> Callable[[Any], bool]:
            return lambda item: (
                isinstance(item, dict)
                and any(
                    entry["msg"].startswith(f"Spawning turtle [{name}]")
                    and entry["level"] == "INFO"
                    for entry in item.get("entries", [])
                )
            )

        async def check(tab: Tab) -> None:
            await tab.until(spawned("turtle1"), "turtlesim's first lines (history)")
            await asyncio.to_thread(
                ok,
                "ros2",
                "service",
                "call",
                "/spawn",
                "turtlesim/srv/Spawn",
                "{x: 2.0, y: 2.0, name: 'log_probe'}",
            )
            await tab.until(spawned("log_probe"), "the line about the new turtle")

        with_tab(viewer, check)

    def test_topic_values_arrive(self, viewer: str) -> None:
        def pose(item: Any) -> Any:
            is_topic = isinstance(item, dict) and item.get("type") == "topic"
            return item if is_topic and item["topic"] == "/turtle1/pose" else None

        async def check(tab: Tab) -> None:
            await tab.ws.send_str(json.dumps({"watch": "/turtle1/pose"}))
            first = await tab.until(pose, "a /turtle1/pose message")
            assert first["type_name"] == "turtlesim/msg/Pose"
            assert set(first["numbers"]) == {
                "x",
                "y",
                "theta",
                "linear_velocity",
                "angular_velocity",
            }
            assert first["yaml"].startswith("x: ")
            await asyncio.to_thread(drive, DRIVE[1])
            moving = await tab.until(
                lambda item: (
                    (found := pose(item)) and found["numbers"]["linear_velocity"] > 0 and found
                ),
                "a pose of the moving turtle",
            )
            assert moving["count"] > first["count"]

        with_tab(viewer, check)

    def test_graph_follows_nodes(self, viewer: str, node_process) -> None:
        def graph(shown: bool) -> Callable[[Any], Any]:
            def check(item: Any) -> Any:
                is_graph = isinstance(item, dict) and item.get("type") == "graph"
                if not is_graph or (">/talker</text>" in item["svg"]) != shown:
                    return None
                # The node may be discovered a refresh before its publisher: wait for both.
                return item if not shown or "/chatter" in item["topics"] else None

            return check

        async def check(tab: Tab) -> None:
            await tab.until(graph(False), "the graph without /talker")
            talker = await asyncio.to_thread(
                node_process, str(BIN / "ros2"), "run", "ros_tutorials_topic", "talker"
            )
            await tab.until(graph(True), "the graph with /talker and /chatter")
            assert await asyncio.to_thread(talker.interrupt) == 0
            await tab.until(graph(False), "the graph without /talker again")

        with_tab(viewer, check)

    def test_bad_messages_and_a_tab_gone_mid_stream(self, viewer: str) -> None:
        async def rude() -> None:
            async with aiohttp.ClientSession() as client:
                ws = await client.ws_connect(at(viewer, "ws"))
                for junk in ("not json", '{"watch": 5}', '{"watch": "no_slash"}', "[]", "{}"):
                    await ws.send_str(junk)
                await ws.send_bytes(b"\x00" * 1000)
                await ws.send_str(json.dumps({"watch": "/turtle1/pose"}))
                await asyncio.sleep(1.0)  # the junk is read (a close would come within it)
                reply = await ws.receive(timeout=TIMEOUT)
                assert reply.type == aiohttp.WSMsgType.TEXT, f"junk closed the tab: {reply}"
                # Gone without a goodbye, in the middle of the stream.
                assert ws._response.connection is not None
                ws._response.connection.transport.abort()

        asyncio.run(rude())

        async def still_serves(tab: Tab) -> None:
            await tab.ws.send_str(json.dumps({"watch": "/turtle1/pose"}))
            await tab.until(
                lambda item: isinstance(item, dict) and item.get("type") == "topic",
                "a message after the other tab went",
            )

        with_tab(viewer, still_serves)

    # --- who may look: Origin, Host, token (what Jupyter and VS Code's servers check) -----

    def test_a_websocket_from_another_web_site_is_refused(self, viewer: str) -> None:
        """Any web page the learner visits can open ws://127.0.0.1:PORT/ws; the browser says
        whose page it is in Origin, and only the viewer's own page may connect."""
        own_page = viewer.split("/?")[0]  # http://127.0.0.1:PORT

        async def check() -> None:
            async with aiohttp.ClientSession() as client:
                with pytest.raises(aiohttp.WSServerHandshakeError) as refused:
                    await client.ws_connect(at(viewer, "ws"), origin="https://evil.example")
                assert refused.value.status == 403
                async with client.get(at(viewer, "api/log"), headers={"Origin": "null"}) as got:
                    assert got.status == 403
                    assert (await got.text()).startswith(
                        "403 Forbidden: Origin 'null' is not this viewer's page"
                    )
                async with client.ws_connect(at(viewer, "ws"), origin=own_page) as ws:
                    assert not ws.closed  # the upgrade was answered: 101

        asyncio.run(check())

    def test_a_request_for_another_host_name_is_refused(self, viewer: str) -> None:
        """DNS rebinding: a web site whose name is made to resolve to 127.0.0.1 reaches the
        viewer with that name in Host, and the browser lets its page read the answers. The
        viewer answers only for the names it listens on."""
        port = int(re.search(r":(\d+)/", viewer).group(1))

        async def check() -> None:
            async with aiohttp.ClientSession() as client:
                for path in ("", "api/topics", "api/log", "ws"):
                    rebound = {"Host": f"rebind.example:{port}"}
                    async with client.get(at(viewer, path), headers=rebound) as got:
                        assert got.status == 403, path
                        assert await got.text() == (
                            f"403 Forbidden: Host 'rebind.example:{port}' is not a name this "
                            "viewer serves\n"
                        )
                for name in ("localhost", "127.0.0.1"):
                    ours = {"Host": f"{name}:{port}"}
                    async with client.get(at(viewer, "api/log"), headers=ours) as got:
                        assert got.status == 200, name

        asyncio.run(check())

    def test_the_token_is_needed(self, viewer: str) -> None:
        """Without the token of the printed link: 403, for the page, the API and the
        WebSocket. Opening the link sets a cookie that carries it from then on."""
        page, token = viewer.split("?token=")
        port = int(re.search(r":(\d+)/", viewer).group(1))

        async def check() -> None:
            async with aiohttp.ClientSession() as client:
                for url in (page, page + "api/log", page + "?token=wrong", page + "api/log?token="):
                    async with client.get(url) as got:
                        assert got.status == 403, url
                        assert "no valid token" in await got.text()
                with pytest.raises(aiohttp.WSServerHandshakeError) as refused:
                    await client.ws_connect(page + "ws")
                assert refused.value.status == 403
                async with client.get(page + "static/viewer.js") as got:
                    assert got.status == 200  # the page's own files hide nothing
                async with client.get(
                    page + "api/log", headers={"Authorization": f"token {token}"}
                ) as got:
                    assert got.status == 200
                async with client.get(viewer) as got:
                    assert got.status == 200
                    cookie = got.cookies[f"ros_viewer_token_{port}"]
                assert cookie.value == token
                assert cookie["httponly"] and cookie["samesite"] == "Strict"
                with_cookie = {"Cookie": f"ros_viewer_token_{port}={token}"}
                async with client.get(page, headers=with_cookie) as got:
                    assert got.status == 200

        asyncio.run(check())

    def test_a_crafted_token_or_path_is_refused_in_one_line(self, viewer: str) -> None:
        """A token of bytes that are not UTF-8 (a header or a cookie) and a path that climbs
        out of /static/: each a 403 like any wrong token, never a 500."""
        port = int(re.search(r":(\d+)/", viewer).group(1))
        for header in (
            b"Authorization: token \xff\xfe",
            b"Cookie: ros_viewer_token_%d=\xff" % port,
        ):
            with socket.create_connection(("127.0.0.1", port), timeout=30) as sock:
                sock.sendall(
                    b"GET /api/log HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n%s\r\n"
                    b"Connection: close\r\n\r\n" % (port, header)
                )
                answer = b""
                while chunk := sock.recv(65536):
                    answer += chunk
            assert answer.startswith(b"HTTP/1.1 403"), answer[:200]
            assert b"no valid token" in answer

        async def check() -> None:
            async with aiohttp.ClientSession() as client:
                page = viewer.split("?token=")[0]
                async with client.get(page + "static/../api/log") as got:
                    assert got.status != 200

        asyncio.run(check())


def test_a_forwarded_port_is_allowed_by_name(own_domain, node_process) -> None:
    """A cloud editor shows the page from an origin of its own (its forwarded port), and its
    proxy may pass that name on in Host: --allow-origin names it, and only it."""
    forwarded = "https://8080-abc.example.dev"
    process = node_process(
        str(BIN / "ros2"), "run", "ros_tutorials_web", "viewer", "--port", "0",
        "--allow-origin", forwarded,
    )  # fmt: skip
    link = re.search(LINK, process.wait_for_text("in a browser")[-1]).group(1)

    async def check() -> None:
        async with aiohttp.ClientSession() as client:
            async with client.ws_connect(at(link, "ws"), origin=forwarded) as ws:
                assert not ws.closed
            proxied = {"Host": "8080-abc.example.dev", "Origin": forwarded}
            async with client.get(at(link, "api/log"), headers=proxied) as got:
                assert got.status == 200
            with pytest.raises(aiohttp.WSServerHandshakeError) as refused:
                await client.ws_connect(at(link, "ws"), origin="https://8081-abc.example.dev")
            assert refused.value.status == 403

    asyncio.run(check())
    # The first refusal of a kind is said in the viewer's terminal too.
    process.wait_for_text("Refused GET /ws: Origin 'https://8081-abc.example.dev'")


def test_every_address_says_so() -> None:
    """--host 0.0.0.0: a link that works here, one for other machines, and a warning that
    anyone on the network can now watch. (A socket bound, never listening: nothing reachable.)"""
    with socket.socket() as sock:
        sock.bind(("0.0.0.0", 0))
        port = sock.getsockname()[1]
        guard = Guard.for_socket(sock, "0.0.0.0", [])
        lines = greeting(sock, guard)
    here = f"http://127.0.0.1:{port}/?token={guard.token}"
    there = f"http://{socket.gethostname()}:{port}/?token={guard.token}"
    assert lines == [
        f"Open {here} in a browser (Ctrl-C to stop); from other machines {there}",
        "Listening on 0.0.0.0, not only on this machine: anyone on the network who has the "
        "link can watch the graph, /rosout and every topic, and call services, publish and set "
        "parameters with the rqt tools",
    ]
    assert guard.hosts is None  # any name: other machines use theirs for this one


class TestBadInput:
    def test_port_out_of_range(self) -> None:
        result = run("viewer", "--port", "70000")
        assert result.returncode == 2, result.stderr
        assert result.stderr.splitlines()[-1] == (
            "viewer: error: argument --port: 70000 is not a port number (0 to 65535)"
        )
        assert "Traceback" not in result.stderr

    def test_port_taken(self) -> None:
        with socket.create_server(("127.0.0.1", 0)) as taken:
            port = taken.getsockname()[1]
            result = run("ros2", "run", "ros_tutorials_web", "viewer", "--port", str(port))
        assert result.returncode == 1, result.stderr
        assert result.stderr.strip() == (
            f"error: port {port} on 127.0.0.1 is in use by another program; "
            "choose another with --port (0: any free)"
        )

    def test_address_not_of_this_machine(self) -> None:
        result = run("viewer", "--host", "192.0.2.1", "--port", "0")  # TEST-NET-1: never ours
        assert result.returncode == 1
        assert result.stderr == (
            "error: cannot listen on 192.0.2.1: not an address of this machine\n"
        )

    def test_allow_origin_not_an_origin(self) -> None:
        result = run("viewer", "--allow-origin", "https://example.dev/path")
        assert result.returncode == 2, result.stderr
        assert result.stderr.splitlines()[-1] == (
            "viewer: error: argument --allow-origin: 'https://example.dev/path' is not an "
            "origin: http(s)://host[:port], e.g. https://8080-x.example.dev"
        )

    def test_unknown_host(self) -> None:
        result = run("viewer", "--host", "no-such-host.invalid", "--port", "0")
        assert result.returncode == 1
        line = result.stderr.strip()
        assert line.startswith("error: cannot listen on 'no-such-host.invalid': ")
        assert "\n" not in line


class TestInBrowser:
    """The page in headless Chromium, opened as a person opens the printed link."""

    def test_canvas_shows_the_trail(self, viewer: str, tmp_path) -> None:
        with chromium() as browser:
            browser.get(viewer)
            before = until(lambda: trail(browser), "a canvas frame drawn")
            drive()
            # Any new trail will do: a loaded machine runs fewer of turtlesim's steps in a second.
            until(lambda: trail(browser) > before + 20, "the trail drawn after a pub")
            assert "live" in browser.find_element("id", "status").text
            browser.save_screenshot(str(tmp_path / "web_viewer.png"))

    def test_the_idle_canvas_after_every_reload(self, viewer: str) -> None:
        """A reload ends the page's WebSocket (the viewer's last tab: it unsubscribes from
        the canvas) and opens another (it subscribes again) within a moment, so turtlesim
        may never see a reader leave and join, and sends no frame for a join: it sends its
        canvas every second while subscribed, and the idle turtle is drawn after each of
        RELOADS reloads (about one in ten missed its frame without that)."""
        with chromium() as browser:
            browser.get(viewer)
            for reload in range(RELOADS):
                until(lambda: trail(browser), f"turtlesim's canvas drawn after {reload} reloads")
                browser.refresh()
            until(lambda: trail(browser), f"turtlesim's canvas drawn after {RELOADS} reloads")


# The pen's pixels in the canvas the page drew (read back from the page), or 0 before the
# first frame is drawn.
COUNT_TRAIL = """
    const [topic, r, g, b] = arguments;
    const canvas = document.querySelector(`canvas[data-topic="${topic}"]`);
    if (!canvas || !window.viewerState.frames[topic]) return 0;
    const box = [0, 0, canvas.width, canvas.height];
    const data = canvas.getContext("2d").getImageData(...box).data;
    let n = 1;  // drawn: at least 1
    for (let i = 0; i < data.length; i += 4)
      if (data[i] === r && data[i + 1] === g && data[i + 2] === b) n++;
    return n;
"""


def trail(browser: Any) -> int:
    return browser.execute_script(COUNT_TRAIL, CANVAS, *DEFAULT_PEN)


# Installed in the page before its own script runs: after every change of the page, what a
# person would see at that moment (the status, whether the "No turtlesim running yet" hint
# shows, whether the graph names /turtlesim), each state once, in order.
WATCH_THE_PAGE = """
    window.seenStates = [];
    let last = "";
    new MutationObserver(() => {
      const status = document.getElementById("status");
      const hint = document.getElementById("no-pictures");
      const graph = document.getElementById("graph");
      if (!status || !hint || !graph) return;
      const seen = {
        status: status.textContent,
        hint: !hint.hidden,
        turtlesim: graph.textContent.includes("/turtlesim"),
      };
      const key = JSON.stringify(seen);
      if (key !== last) window.seenStates.push(seen);
      last = key;
    }).observe(document, { subtree: true, childList: true, characterData: true, attributes: true });
"""


def test_a_page_opened_later_shows_turtlesim_started_with_the_viewer(
    own_domain, node_process
) -> None:
    """turtlesim and the viewer started at once, as two terminals start them, the link opened
    once both run: the page shows turtlesim in the graph and its idle canvas, and at no
    moment says live with an empty graph or says no turtlesim runs (a screenshot taken as
    the page opens would show that moment)."""
    sim = node_process(str(BIN / "ros2"), "run", "turtlesim", "turtlesim_node", env=HEADLESS)
    process = node_process(str(BIN / "ros2"), "run", "ros_tutorials_web", "viewer", "--port", "0")
    sim.wait_for_text("Spawning turtle [turtle1]")
    link = re.search(LINK, process.wait_for_text("in a browser")[-1]).group(1)
    graph = at(link, "api/graph.svg")

    def graph_lists_turtlesim() -> bool:
        with urllib.request.urlopen(graph, timeout=TIMEOUT) as answer:
            return "/turtlesim" in answer.read().decode()

    until(graph_lists_turtlesim, "turtlesim in /api/graph.svg")
    with chromium() as browser:
        browser.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": WATCH_THE_PAGE})
        browser.get(link)
        until(lambda: "/turtlesim" in text_of(browser, "#graph"), "/turtlesim in the graph")
        until(lambda: trail(browser), "turtlesim's canvas drawn")
        assert browser.find_element("id", "no-pictures").is_displayed() is False
        assert browser.find_element("id", "status").text == "live"
        seen = browser.execute_script("return window.seenStates")
    assert seen, "the page's states were not recorded"
    false = [state for state in seen if state["status"] == "live" and not state["turtlesim"]]
    assert not false, f"the page said live without turtlesim in its graph: {seen}"
    hinted = [state for state in seen if state["hint"]]
    assert not hinted, f"the page said no turtlesim runs while it ran: {seen}"
