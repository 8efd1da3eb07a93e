"""A page's WebSocket read in a thread of its own, for the browser-view benchmarks (web.py,
rviz.py): each binary frame's JSON header (4-byte length, then the header) goes to
``on_frame`` with the time it arrived; ``stop`` ends the reading, ``error`` is what ended it."""

from __future__ import annotations

import asyncio
import json
import struct
import threading
import time
from typing import Any

import aiohttp


class FrameReader(threading.Thread):
    def __init__(self, url: str) -> None:
        super().__init__(daemon=True)
        self.url = url
        self.latencies: list[float] = []
        self.stop = threading.Event()
        self.error: BaseException | None = None

    def on_frame(self, header: dict[str, Any], now: float) -> None:
        """One frame's header, and time.time() when it arrived."""

    def run(self) -> None:
        try:
            asyncio.run(self._read())
        except BaseException as error:
            self.error = error

    async def _read(self) -> None:
        async with aiohttp.ClientSession() as client, client.ws_connect(self.url) as ws:
            while not self.stop.is_set():
                try:
                    message = await ws.receive(timeout=0.2)
                except asyncio.TimeoutError:
                    continue
                if message.type != aiohttp.WSMsgType.BINARY:
                    continue
                now = time.time()
                (length,) = struct.unpack("!I", message.data[:4])
                self.on_frame(json.loads(message.data[4 : 4 + length]), now)
