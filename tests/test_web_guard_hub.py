"""The web servers' shared parts without ROS: the hub (keys started by the first tab, stopped
by the last, the present state sent to a tab that comes later) and the guard's writing
routes (a POST of JSON from the server's own page, nothing else), over a real socket with
aiohttp's client."""

from __future__ import annotations

import asyncio
import json

import aiohttp
from aiohttp import web
from rclpy.serialization import deserialize_message, serialize_message

from ros_tutorials_web import guard
from ros_tutorials_web.hub import Hub, Tab
from ros_tutorials_web.watch import Feed


class FakeSocket:
    """Where a Tab sends: only whether it is closed is read before sending."""

    closed = False


def test_keys_start_with_the_first_tab_and_stop_with_the_last() -> None:
    async def check() -> None:
        ran: list[str] = []
        hub = Hub(
            asyncio.get_running_loop(),
            ros=lambda change: change(),
            start=lambda key: ran.append("start " + key),
            stop=lambda key: ran.append("stop " + key),
            always=("graph",),
        )
        one, two = Tab(FakeSocket()), Tab(FakeSocket())
        hub.add(one, ("graph", "topic:/a"))
        hub.add(two, ("graph", "topic:/a"))
        assert ran == ["start topic:/a"]  # shared: started once, "graph" never
        hub.offer("topic:/a", "A1", "topic")
        hub.remove(one)
        assert ran == ["start topic:/a"]
        hub.remove(two)
        assert ran == ["start topic:/a", "stop topic:/a"]
        assert hub.newest("topic:/a", "topic") is None  # forgotten with its last tab
        hub.offer("topic:/a", "late")  # came after the last tab went: not kept
        assert hub.newest("topic:/a") is None

    asyncio.run(check())


def test_a_tab_that_comes_later_gets_the_present_state() -> None:
    async def check() -> None:
        hub = Hub(asyncio.get_running_loop(), always=("graph", "log"))
        hub.offer("graph", "G1")
        hub.offer("graph", "G2")  # kept: the newest only
        hub.extend("log", [{"msg": "one"}, {"msg": "two"}])
        tab = Tab(FakeSocket())
        hub.add(tab, ("graph", "log"))
        assert tab._pending == {"graph": "G2"}
        assert list(tab._lists["log"]) == [{"msg": "one"}, {"msg": "two"}]
        hub.offer("graph", "G3")
        assert tab._pending == {"graph": "G3"}  # a slow tab gets the newest, not a queue

    asyncio.run(check())


def test_writing_routes_need_a_post_of_json_from_the_own_page() -> None:
    async def check() -> None:
        sock = guard.listen("127.0.0.1", 0)
        door = guard.Guard.for_socket(sock, "127.0.0.1", [])
        done: list[dict] = []

        async def call(request: web.Request) -> web.Response:
            done.append(await request.json())
            return web.json_response({"ok": True})

        app = web.Application(middlewares=[door.middleware(lambda line: None)])
        app.router.add_route("*", "/api/call", door.writes(call))
        runner = web.AppRunner(app)
        await runner.setup()
        await web.SockSite(runner, sock).start()
        port = sock.getsockname()[1]
        url = f"http://127.0.0.1:{port}/api/call"
        own = {"Origin": f"http://127.0.0.1:{port}", "Authorization": f"token {door.token}"}
        try:
            async with aiohttp.ClientSession() as client:

                async def status(method: str, headers: dict, data: str = "{}") -> int:
                    async with client.request(method, url, headers=headers, data=data) as got:
                        return got.status

                json_type = {"Content-Type": "application/json"}
                assert await status("POST", {**own, **json_type}, json.dumps({"x": 1})) == 200
                assert done == [{"x": 1}]
                assert await status("GET", own) == 403
                form = {"Content-Type": "application/x-www-form-urlencoded"}
                assert await status("POST", {**own, **form}) == 403
                no_origin = {"Authorization": own["Authorization"], **json_type}
                assert await status("POST", no_origin) == 403
                other = {**own, **json_type, "Origin": "https://evil.example.com"}
                assert await status("POST", other) == 403
                no_token = {"Origin": own["Origin"], **json_type}
                assert await status("POST", no_token) == 403
                assert done == [{"x": 1}]  # none of the refused ones ran
        finally:
            await runner.cleanup()
            sock.close()

    asyncio.run(check())


def test_a_feed_keeps_every_message_for_a_plot_within_its_bytes() -> None:
    """A plot draws every message of a topic, not only the newest the viewer passes on at
    its stream rate; what is kept between two takes is bounded in bytes (oldest dropped)."""
    from std_msgs.msg import Float64

    from ros_tutorials_web import watch

    woken: list[Feed] = []
    feed = Feed("/fast", "std_msgs/msg/Float64", woken.append)
    for value in range(5):
        feed.put(serialize_message(Float64(data=float(value))))
    assert len(woken) == 1  # the event loop is woken once until it takes
    assert feed.take() == serialize_message(Float64(data=4.0))  # the newest
    history = feed.take_history()
    values = [deserialize_message(data, Float64).data for _, data in history]
    assert values == [0.0, 1.0, 2.0, 3.0, 4.0]
    assert [came for came, _ in history] == sorted(came for came, _ in history)
    assert feed.take_history() == []
    big = b"\0" * (watch.HISTORY_BYTES // 3)
    for _ in range(5):
        feed.put(big)
    assert len(feed.take_history()) == 3  # the oldest went first
