"""rqt in the browser: the server side of rqt's plugins, at ``/rqt`` beside the viewer's page
(static/rqt.html and rqt.js draw them; the viewer's panels are rqt_graph and rqt_console).
(Six plugins of a few routes each, on the one node (``Ros``), the hub's tabs and the guard
they share. What the routes convert lives below them: forms.py reads the forms and the typed
parameter values, on ros2cmd's message filling and parameter types; ros2cmd.log asks and
reads the logger services; ros2cmd.graph lists the nodes and services.)

    Service Caller   GET  /api/rqt/services             services and their types
                     GET  /api/rqt/interface?type=T     a message's (a request's) fields, a form
                     POST /api/rqt/call                 {service, type, request} -> the response
    Publisher        WebSocket {"publish": {id, topic, type, message, rate, on}}
                       -> {"type": "publisher", id, count | error}; the tab's publishers go
                       with it
    Parameters       GET  /api/rqt/nodes                the nodes
    (rqt_reconfigure) GET /api/rqt/params?node=N        each parameter: type, value, range ...
                     POST /api/rqt/param                {node, name, value} -> set, or the reason
    Logger levels    GET  /api/rqt/logger?node=N        the node's level
                     POST /api/rqt/logger               {node, level}
    Plot             WebSocket {"plot": [TOPIC, ...]} -> {"type": "topic", ...} for each
    Bag              GET  /api/rqt/bag?path=P           its topics on a time line
                     GET  /api/rqt/bag/message?path=P&topic=T&index=I   one message
                     WebSocket {"play": {id, path, start, end, topics}} (or {"play": null})
                       -> {"type": "play", id, at, count | done | error}

Every writing route is behind Guard.writes (a POST of JSON from the page itself, with the
token); a WebSocket's messages passed the guard when it opened. A request or message that
does not fit its type is answered with one line (HTTP 400 ``{"error": ...}``, or the
``error`` of a WebSocket answer) and nothing is sent. Values come from the form as the text
typed in each field; a string field takes it as typed, any other field reads it as YAML
(``2``, ``true``, ``[1, 2]``) before ros2cmd.messages fills the message and checks it.

Service clients and parameter clients are made for one call and destroyed after it;
publishers and plot subscriptions belong to the tab that asked and go with it. forms.py
reads the forms, ros_calls.py does the node's part.
"""

from __future__ import annotations

import asyncio
import json
import math
import os
import time
import weakref
from pathlib import Path
from typing import Any

from aiohttp import web

from ros2cmd.console import LEVELS
from ros2cmd.messages import message_to_ordered, message_to_yaml
from ros_tutorials_web.forms import (
    Refused,
    filled,
    form,
    is_number,
    parameter_entry,
    parameter_value,
    plain_data,
    type_class,
)
from ros_tutorials_web.guard import Guard
from ros_tutorials_web.hub import Hub, Tab
from ros_tutorials_web.ros_calls import Ros
from ros_tutorials_web.watch import NodeGraph
from rosbag2.errors import BagError
from rosbag2.reader import BagReader

STATIC = Path(__file__).resolve().parent / "static"
MAX_RATE = 100.0  # Hz: the fastest a page may publish
TIMELINE_POINTS = 2000  # per topic: a bag's time line is decimated to this many stamps
BAG_MESSAGE_TEXT = 20000  # characters of one bag message shown
PLOT_TOPICS = 10  # topics one tab may plot at once


# --- the tools ---------------------------------------------------------------------------------


class Timeline:
    """A topic's message times as its time line shows them: at most TIMELINE_POINTS stamps,
    spread evenly over the messages, kept in memory that does not grow with the bag (every
    ``stride``-th message is kept; when twice the points are kept, every other one goes and the
    stride doubles)."""

    def __init__(self) -> None:
        self.count = 0
        self.stride = 1
        self.kept: list[int] = []

    def add(self, stamp: int) -> None:
        if self.count % self.stride == 0:
            self.kept.append(stamp)
            if len(self.kept) == 2 * TIMELINE_POINTS:
                del self.kept[1::2]
                self.stride *= 2
        self.count += 1

    def stamps(self) -> list[int]:
        return self.kept[:: max(1, math.ceil(len(self.kept) / TIMELINE_POINTS))]


class Tools:
    """The rqt tools' routes and WebSocket messages, on one node (the viewer's)."""

    def __init__(self, ros: Ros, hub: Hub) -> None:
        self.ros = ros
        self.hub = hub
        # Per tab: its publishers and its bag player, by the page's id (tasks of the tab's:
        # cancelled, with what they made, when the tab goes).
        self.publishing: weakref.WeakKeyDictionary[Tab, dict[Any, asyncio.Task]] = (
            weakref.WeakKeyDictionary()
        )

    def add_routes(self, app: web.Application, door: Guard) -> None:
        get, post = app.router.add_get, app.router.add_post
        get("/rqt", self.page)
        get("/api/rqt/services", self.services)
        get("/api/rqt/interface", self.interface)
        post("/api/rqt/call", door.writes(self.call))
        get("/api/rqt/nodes", self.nodes)
        get("/api/rqt/params", self.params)
        post("/api/rqt/param", door.writes(self.set_param))
        get("/api/rqt/logger", self.logger)
        post("/api/rqt/logger", door.writes(self.set_logger))
        get("/api/rqt/bag", self.bag)
        get("/api/rqt/bag/message", self.bag_message)

    async def page(self, _request: web.Request) -> web.FileResponse:
        return web.FileResponse(STATIC / "rqt.html")

    # Each handler answers one line on a Refused.
    @staticmethod
    def refused(error: Exception) -> web.Response:
        return web.json_response({"error": str(error)}, status=400)

    async def body(self, request: web.Request) -> dict[str, Any]:
        try:
            data = await request.json()
        except (ValueError, UnicodeDecodeError):
            raise Refused("the request's body is not JSON") from None
        if not isinstance(data, dict):
            raise Refused("the request's body is not a JSON object")
        return data

    # --- Service Caller ------------------------------------------------------------------------

    async def services(self, _request: web.Request) -> web.Response:
        found = await self.ros.run(NodeGraph(self.ros.node).service_types)
        return web.json_response(dict(sorted(found.items())))

    async def interface(self, request: web.Request) -> web.Response:
        name = request.query.get("type", "")
        try:
            if "/srv/" in name:
                cls = type_class(name, ("srv",))
                return web.json_response(
                    {"request": form(cls.Request), "response": form(cls.Response)}
                )
            return web.json_response({"message": form(type_class(name, ("msg",)))})
        except Refused as error:
            return self.refused(error)

    async def call(self, request: web.Request) -> web.Response:
        try:
            data = await self.body(request)
            service = data.get("service")
            if not isinstance(service, str) or not service.startswith("/"):
                raise Refused("no service chosen")
            cls = type_class(data.get("type"), ("srv",))
            message = filled(cls.Request, data.get("request", {}))
            started = time.monotonic()
            response = await self.ros.call(service, cls, message, f"calling '{service}'")
        except Refused as error:
            return self.refused(error)
        return web.json_response(
            {
                "yaml": message_to_yaml(response) if response.get_fields_and_field_types() else "",
                "data": plain_data(message_to_ordered(response)),
                "seconds": round(time.monotonic() - started, 3),
            }
        )

    # --- Parameters ------------------------------------------------------------------------------

    async def nodes(self, _request: web.Request) -> web.Response:
        own = self.ros.node.get_fully_qualified_name()
        names = await self.ros.run(NodeGraph(self.ros.node).node_names)
        return web.json_response(sorted({name for name in names if name != own}))

    def node_name(self, given: Any) -> str:
        if not isinstance(given, str) or not given.strip("/"):
            raise Refused("no node chosen")
        return "/" + given.strip("/")

    async def params(self, request: web.Request) -> web.Response:
        from rcl_interfaces.srv import DescribeParameters, GetParameters, ListParameters

        try:
            node = self.node_name(request.query.get("node"))
            listed = await self.ros.call(
                f"{node}/list_parameters", ListParameters, ListParameters.Request(),
                f"listing the parameters of '{node}'",
            )  # fmt: skip
            names = sorted(listed.result.names)
            values = await self.ros.call(
                f"{node}/get_parameters", GetParameters, GetParameters.Request(names=names),
                f"getting the parameters of '{node}'",
            )  # fmt: skip
            described = await self.ros.call(
                f"{node}/describe_parameters", DescribeParameters,
                DescribeParameters.Request(names=names), f"describing the parameters of '{node}'",
            )  # fmt: skip
        except Refused as error:
            return self.refused(error)
        entries = [
            parameter_entry(name, value, descriptor)
            for name, value, descriptor in zip(
                names, values.values, described.descriptors, strict=False
            )
        ]
        return web.json_response({"node": node, "parameters": entries})

    async def set_param(self, request: web.Request) -> web.Response:
        from rcl_interfaces.msg import Parameter
        from rcl_interfaces.srv import SetParameters

        try:
            data = await self.body(request)
            node = self.node_name(data.get("node"))
            name, kind = data.get("name"), data.get("type")
            if not isinstance(name, str) or not name or not isinstance(kind, str):
                raise Refused("no parameter chosen")
            value = parameter_value(data.get("value"), kind)
            answer = await self.ros.call(
                f"{node}/set_parameters", SetParameters,
                SetParameters.Request(parameters=[Parameter(name=name, value=value)]),
                f"setting '{name}' of '{node}'",
            )  # fmt: skip
        except Refused as error:
            return self.refused(error)
        result = answer.results[0] if answer.results else None
        if result is None or not result.successful:
            reason = result.reason if result is not None and result.reason else "refused"
            return self.refused(Refused(f"'{node}' refused {name}: {reason}"))
        return web.json_response({"ok": True})

    # --- Logger levels ----------------------------------------------------------------------------

    async def logger(self, request: web.Request) -> web.Response:
        from rcl_interfaces.srv import GetLoggerLevels

        from ros2cmd.log import GET, get_request, level_in

        try:
            node = self.node_name(request.query.get("node"))
            answer = await self.ros.call(
                f"{node}/{GET}", GetLoggerLevels, get_request(node),
                f"getting the logger level of '{node}'",
            )  # fmt: skip
        except Refused as error:
            return self.refused(error)
        return web.json_response({"node": node, "level": level_in(answer)})

    async def set_logger(self, request: web.Request) -> web.Response:
        from rcl_interfaces.srv import SetLoggerLevels

        from ros2cmd.log import SET, refusal, set_request

        try:
            data = await self.body(request)
            node = self.node_name(data.get("node"))
            level = str(data.get("level", "")).lower()
            if level not in LEVELS:
                raise Refused(f"{data.get('level')!r} is not a level ({', '.join(LEVELS)})")
            answer = await self.ros.call(
                f"{node}/{SET}", SetLoggerLevels, set_request(node, level),
                f"setting the logger level of '{node}'",
            )  # fmt: skip
        except Refused as error:
            return self.refused(error)
        refused = refusal(node, level, answer)
        if refused is not None:
            return self.refused(Refused(refused))
        return web.json_response({"ok": True, "level": level.upper()})

    # --- Bag -----------------------------------------------------------------------------------

    def open_bag(self, given: Any) -> BagReader:
        if not isinstance(given, str) or not given.strip():
            raise Refused("no bag given: the path of a bag folder or .mcap file")
        path = Path(os.path.expanduser(given.strip()))
        if not path.is_absolute():
            path = Path.cwd() / path
        try:
            return BagReader(path)
        except BagError as error:
            raise Refused(str(error)) from None

    async def bag(self, request: web.Request) -> web.Response:
        try:
            answer = await asyncio.to_thread(self.bag_outline, request.query.get("path"))
        except Refused as error:
            return self.refused(error)
        return web.json_response(answer)

    def bag_outline(self, given: Any) -> dict[str, Any]:
        """The bag's topics with the times of their messages (decimated), read once."""
        with self.open_bag(given) as reader:
            bag = reader.bag
            lines = {name: Timeline() for name in bag.topics}
            try:
                for message in reader.messages():
                    lines.setdefault(message.topic, Timeline()).add(message.log_time)
            except BagError as error:
                raise Refused(str(error)) from None
        topics = []
        for name, info in sorted(bag.topics.items()):
            line = lines.get(name, Timeline())
            topics.append(
                {
                    "name": name,
                    "type": info.type,
                    "count": line.count,
                    "times": [(t - bag.start) / 1e9 for t in line.stamps()],
                }
            )
        return {
            "path": str(reader.path),
            "start": bag.start / 1e9,
            "duration": (bag.end - bag.start) / 1e9,
            "topics": topics,
        }

    async def bag_message(self, request: web.Request) -> web.Response:
        query = request.query
        try:
            at = float(query.get("at", ""))
        except ValueError:
            return self.refused(Refused("'at' is not a time in seconds"))
        try:
            answer = await asyncio.to_thread(
                self.message_at, query.get("path"), query.get("topic", ""), at
            )
        except Refused as error:
            return self.refused(error)
        return web.json_response(answer)

    def message_at(self, given: Any, topic: str, at: float) -> dict[str, Any]:
        """The topic's last message at ``at`` seconds from the bag's start (or its first)."""
        from rclpy.serialization import deserialize_message

        with self.open_bag(given) as reader:
            info = reader.bag.topics.get(topic)
            if info is None:
                raise Refused(f"the bag has no topic {topic!r}")
            moment = reader.bag.start + int(at * 1e9)
            found = None
            index = -1
            try:
                for message in reader.messages([topic]):
                    if found is not None and message.log_time > moment:
                        break
                    found, index = message, index + 1
            except BagError as error:
                raise Refused(str(error)) from None
            if found is None:
                raise Refused(f"{topic} has no messages in the bag")
            cls = type_class(info.type, ("msg",))
            try:
                msg = deserialize_message(found.data, cls)
            except Exception as error:
                raise Refused(f"a message of {topic} cannot be read: {error}") from None
            return {
                "topic": topic,
                "type": info.type,
                "index": index,
                "at": (found.log_time - reader.bag.start) / 1e9,
                "yaml": message_to_yaml(msg, truncate_length=64)[:BAG_MESSAGE_TEXT],
            }

    # --- WebSocket messages: publish, plot, play ----------------------------------------------

    def asked(self, tab: Tab, message: dict[str, Any]) -> Any:
        """A tab's message for the tools; an awaitable to run as the tab's task, or None."""
        if "publish" in message:
            return self.publish(tab, message["publish"])
        if "plot" in message:
            topics = message["plot"]
            if isinstance(topics, list) and all(
                isinstance(t, str) and t.startswith("/") for t in topics
            ):
                wanted = {"plot:" + t for t in topics[:PLOT_TOPICS]}
                for key in [k for k in tab.wants if k.startswith("plot:") and k not in wanted]:
                    self.hub.drop(tab, key)
                for key in sorted(wanted):
                    self.hub.want(tab, key)
            return None
        if "play" in message:
            return self.play(tab, message["play"])
        return None

    def answer(self, tab: Tab, payload: dict[str, Any]) -> None:
        tab.offer(f"{payload['type']}:{payload.get('id')}", json.dumps(payload))

    def replace_task(self, tab: Tab, key: Any) -> None:
        """Stop what the tab had running under ``key`` (a publisher, a player)."""
        running = self.publishing.setdefault(tab, {}).pop(key, None)
        if running is not None:
            running.cancel()

    async def publish(self, tab: Tab, asked: Any) -> None:
        """Publish as the page asked: once (rate 0) or at a rate until turned off, or until
        the tab goes; the publisher is made for it and destroyed after."""
        ident = asked.get("id") if isinstance(asked, dict) else None
        key = ("publish", str(ident))
        self.replace_task(tab, key)
        reply = {"type": "publisher", "id": ident}
        try:
            if not isinstance(asked, dict):
                raise Refused("expected {id, topic, type, message, rate, on}")
            if not asked.get("on"):
                self.answer(tab, {**reply, "count": 0, "on": False})
                return
            topic = asked.get("topic")
            if not isinstance(topic, str) or not topic.startswith("/") or len(topic) > 256:
                raise Refused("no topic: a name such as /turtle1/cmd_vel")
            cls = type_class(asked.get("type"), ("msg",))
            message = filled(cls, asked.get("message", {}))
            rate = asked.get("rate", 1.0)
            if not is_number(rate) or not 0 <= rate <= MAX_RATE:
                raise Refused(f"the rate must be 0 (once) to {MAX_RATE:.0f} Hz")
        except Refused as error:
            self.answer(tab, {**reply, "error": str(error), "on": False})
            return
        task = asyncio.current_task()
        assert task is not None
        self.publishing.setdefault(tab, {})[key] = task
        publisher = await self.ros.run(lambda: self.ros.node.create_publisher(cls, topic, 10))
        count = 0
        try:
            while True:
                publisher.publish(message)  # rclpy's publish may be called from any thread
                count += 1
                self.answer(tab, {**reply, "count": count, "on": rate > 0, "topic": topic})
                if rate == 0:
                    break
                await asyncio.sleep(1 / rate)
        finally:
            self.publishing.get(tab, {}).pop(key, None)
            # Destroyed on the ROS thread whether this task ends or is cancelled.
            self.ros.request(lambda: self.ros.node.destroy_publisher(publisher))

    async def play(self, tab: Tab, asked: Any) -> None:
        """Play a range of a bag's messages on their topics, at their recorded pace."""
        from rclpy.serialization import deserialize_message

        key = ("play", "bag")
        self.replace_task(tab, key)
        if asked is None:
            return
        ident = asked.get("id") if isinstance(asked, dict) else None
        reply = {"type": "play", "id": ident}
        try:
            if not isinstance(asked, dict):
                raise Refused("expected {id, path, start, end, topics}")
            start, end = asked.get("start", 0), asked.get("end", math.inf)
            if not is_number(start) or not is_number(end) or end < start:
                raise Refused("the range must be two times in seconds, start before end")
            reader = self.open_bag(asked.get("path"))
        except Refused as error:
            self.answer(tab, {**reply, "error": str(error)})
            return
        task = asyncio.current_task()
        assert task is not None
        self.publishing.setdefault(tab, {})[key] = task
        publishers: dict[str, Any] = {}
        count = 0
        try:
            bag = reader.bag
            chosen = asked.get("topics")
            topics = [t for t in bag.topics if not isinstance(chosen, list) or t in chosen]
            classes = {}
            for name in topics:
                try:
                    classes[name] = type_class(bag.topics[name].type, ("msg",))
                except Refused:
                    continue  # a type not installed here: its messages are not played
            first = bag.start + int(start * 1e9)
            last = bag.start + int(min(end, 1e7) * 1e9)
            began = time.monotonic()
            messages = reader.messages(list(classes), first)
            while True:
                message = await asyncio.to_thread(next, messages, None)
                if message is None or message.log_time > last:
                    break
                wait = (message.log_time - first) / 1e9 - (time.monotonic() - began)
                if wait > 0:
                    await asyncio.sleep(wait)
                cls = classes[message.topic]
                if message.topic not in publishers:
                    publishers[message.topic] = await self.ros.run(
                        lambda t=message.topic, c=cls: self.ros.node.create_publisher(c, t, 10)
                    )
                try:
                    msg = deserialize_message(message.data, cls)
                except Exception:
                    continue  # a message its type cannot read: skipped
                publishers[message.topic].publish(msg)
                count += 1
                at = (message.log_time - bag.start) / 1e9
                self.answer(tab, {**reply, "count": count, "at": at})
            self.answer(tab, {**reply, "count": count, "done": True})
        except BagError as error:
            self.answer(tab, {**reply, "error": str(error)})
        finally:
            reader.close()
            self.publishing.get(tab, {}).pop(key, None)
            for publisher in publishers.values():
                self.ros.request(lambda p=publisher: self.ros.node.destroy_publisher(p))
