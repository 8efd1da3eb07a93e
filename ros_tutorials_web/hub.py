"""The hub: what the ROS side of a web server hands over, passed on to the browser tabs that
want it, with the ROS subscriptions behind it shared by the tabs and released when the last
tab that wanted them goes.

Three threads of thought, kept apart:

- a **Tab** is one browser tab's WebSocket. Per *slot* it holds only the newest payload not
  sent yet (a slow or stalled tab misses frames, it never makes the server queue them);
  list streams (a log) keep their newest entries, bounded.
- a **key** names something a tab wants (``"graph"``, ``"topic:/turtle1/pose"``): the first
  tab to want a key starts it (``start(key)``, run on the ROS thread), the last tab to drop
  it, or to go away, stops it (``stop(key)``). Keys in ``Hub.always`` are fed whether or not
  a tab looks (``start``/``stop`` are not called for them).
- the hub keeps each key's newest payload per slot, so a tab that comes later is sent the
  present state at once, not only what changes after it came; a key's kept payloads are
  forgotten when its last tab goes (unless it is in ``always``).

All of Hub runs on the event loop; the ROS thread only hands over, with ``Hub.from_ros``
(call_soon_threadsafe). ``ros`` (given to the hub) runs a function on the ROS thread: the
only place subscriptions are made and destroyed (watch.Watcher.request is one).

Using it for another tool's page (a 3D view's stream of tf, say)::

    hub = Hub(loop, node.request, start=node.start, stop=node.stop, always={"graph"})
    # the ROS side, on its thread:       hub.from_ros(hub.offer, "tf:world", payload)
    # a WebSocket route, on the loop: the tab wants "tf:world" from the start (the first
    # tab: node.start("tf:world") on the ROS thread), its messages go to on_text (which may
    # hub.want / hub.drop more keys); when it goes, the last tab's keys are stopped.
    async def stream(request):
        ws = web.WebSocketResponse(heartbeat=20, max_msg_size=64 * 1024)
        await ws.prepare(request)
        await hub.session(ws, ["tf:world"], on_text)
        return ws

A payload is a str (a WebSocket text frame, JSON by convention with a ``type``) or bytes (a
binary frame).
"""

from __future__ import annotations

import asyncio
import contextlib
import inspect
import json
from collections import deque
from collections.abc import Callable, Iterable
from typing import Any

from aiohttp import WSMsgType, web

LIST_KEEP = 1000  # entries of a list stream (a log) kept for a tab, and for tabs to come

Payload = str | bytes


class Tab:
    """One browser tab's WebSocket: per slot, the newest payload not sent yet."""

    def __init__(self, ws: web.WebSocketResponse) -> None:
        self.ws = ws
        self.wants: set[str] = set()  # the keys this tab wants (Hub.want)
        self._pending: dict[str, Payload] = {}
        self._lists: dict[str, deque[Any]] = {}
        self._ready = asyncio.Event()

    def offer(self, slot: str, payload: Payload) -> None:
        self._pending[slot] = payload  # replaces what a slow tab has not taken yet
        self._ready.set()

    def extend(self, kind: str, entries: Iterable[Any]) -> None:
        """Entries of a list stream, sent as ``{"type": kind, "entries": [...]}``."""
        self._lists.setdefault(kind, deque(maxlen=LIST_KEEP)).extend(entries)
        self._ready.set()

    async def send(self) -> None:
        """Send what is pending, as it comes, until the tab goes."""
        while not self.ws.closed:
            await self._ready.wait()
            self._ready.clear()
            for kind, entries in self._lists.items():
                if entries:
                    batch = list(entries)
                    entries.clear()
                    await self.ws.send_str(json.dumps({"type": kind, "entries": batch}))
            while self._pending:
                payload = self._pending.pop(next(iter(self._pending)))
                if isinstance(payload, bytes):
                    await self.ws.send_bytes(payload)
                else:
                    await self.ws.send_str(payload)


class Hub:
    """The tabs, the keys they want, and each key's newest payloads (on the event loop)."""

    def __init__(
        self,
        loop: asyncio.AbstractEventLoop,
        ros: Callable[[Callable[[], None]], None] | None = None,
        start: Callable[[str], None] | None = None,
        stop: Callable[[str], None] | None = None,
        always: Iterable[str] = (),
    ) -> None:
        self.loop = loop
        # Set before the first tab comes, when the node is made after the hub.
        self.ros = ros or (lambda change: change())
        self.start = start
        self.stop = stop
        self.always = set(always)
        self.tabs: set[Tab] = set()
        self.kept: dict[str, dict[str, Payload]] = {}  # key -> slot -> newest payload
        self.lists: dict[str, deque[Any]] = {}  # key -> newest entries of a list stream

    def from_ros(self, change: Callable[..., None], *args: Any) -> None:
        """Run change(*args) on the event loop (called on the ROS thread)."""
        self.loop.call_soon_threadsafe(change, *args)

    # --- what the ROS side hands over (on the loop) -----------------------------------------

    def offer(self, key: str, payload: Payload, slot: str | None = None) -> None:
        """The newest payload of ``key`` (in ``slot``, default the key): kept for tabs to
        come, and offered to every tab that wants the key."""
        if key not in self.always and not self.wanted(key):
            return  # its tabs have gone meanwhile: nothing to keep it for
        slot = slot or key
        self.kept.setdefault(key, {})[slot] = payload
        for tab in self.tabs:
            if key in tab.wants:
                tab.offer(slot, payload)

    def extend(self, key: str, entries: list[Any]) -> None:
        """New entries of a list stream (a tab gets ``{"type": key, "entries": [...]}``)."""
        self.lists.setdefault(key, deque(maxlen=LIST_KEEP)).extend(entries)
        for tab in self.tabs:
            if key in tab.wants:
                tab.extend(key, entries)

    def forget(self, key: str, slot: str | None = None) -> None:
        """Drop a kept payload (the slot) or all of a key's (no slot)."""
        if slot is None:
            self.kept.pop(key, None)
        else:
            self.kept.get(key, {}).pop(slot, None)

    def newest(self, key: str, slot: str | None = None) -> Payload | None:
        return self.kept.get(key, {}).get(slot or key)

    # --- tabs coming, wanting and going -----------------------------------------------------

    def wanted(self, key: str) -> bool:
        return any(key in tab.wants for tab in self.tabs)

    def add(self, tab: Tab, keys: Iterable[str] = ()) -> None:
        self.tabs.add(tab)
        for key in keys:
            self.want(tab, key)

    def want(self, tab: Tab, key: str) -> None:
        """The tab wants ``key``: sent its kept payloads now, and what comes from now on."""
        if key in tab.wants:
            return
        first = not self.wanted(key)
        tab.wants.add(key)
        if first and key not in self.always and self.start is not None:
            self.ros(lambda: self.start(key))  # type: ignore[misc]
        for slot, payload in self.kept.get(key, {}).items():
            tab.offer(slot, payload)
        if self.lists.get(key):
            tab.extend(key, self.lists[key])

    def drop(self, tab: Tab, key: str) -> None:
        """The tab no longer wants ``key``; the last one to drop it stops it."""
        if key not in tab.wants:
            return
        tab.wants.discard(key)
        if not self.wanted(key) and key not in self.always:
            self.forget(key)  # not fed any more: what is kept would only grow old
            self.lists.pop(key, None)
            if self.stop is not None:
                self.ros(lambda: self.stop(key))  # type: ignore[misc]

    def remove(self, tab: Tab) -> None:
        """The tab has gone: every key it wanted is dropped."""
        for key in list(tab.wants):
            self.drop(tab, key)
        self.tabs.discard(tab)

    async def session(
        self,
        ws: web.WebSocketResponse,
        keys: Iterable[str],
        on_text: Callable[[Tab, str], Any] = lambda tab, text: None,
    ) -> None:
        """A prepared WebSocket's life as a tab: it wants ``keys`` from the start; each text
        message goes to on_text(tab, text) (an awaitable it returns runs as a task of the
        tab's, cancelled when the tab goes); when the tab goes, its keys are dropped. A tab
        whose sending fails is closed (its page then says so and reconnects), never left
        open and silent."""
        tab = Tab(ws)
        self.add(tab, keys)
        sender = asyncio.create_task(tab.send())

        def sent(task: asyncio.Task) -> None:
            if not task.cancelled() and task.exception() is not None:
                self.loop.create_task(ws.close())

        sender.add_done_callback(sent)
        tasks: set[asyncio.Task] = set()
        try:
            async for message in ws:
                if message.type != WSMsgType.TEXT:
                    continue
                answer = on_text(tab, message.data)
                if inspect.isawaitable(answer):
                    task = asyncio.ensure_future(answer)
                    tasks.add(task)
                    task.add_done_callback(tasks.discard)
        finally:
            for task in (sender, *tasks):
                task.cancel()
            self.remove(tab)
            with contextlib.suppress(asyncio.CancelledError, ConnectionError):
                await sender

    async def close(self, _app: Any = None) -> None:
        """Close every tab's WebSocket (an aiohttp ``on_shutdown`` handler)."""
        for tab in list(self.tabs):
            with contextlib.suppress(Exception):
                await tab.ws.close()
