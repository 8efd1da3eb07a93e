"""Web viewer figures: how late turtlesim's canvas reaches a browser, how often, and what it
costs turtlesim and the viewer; at 1 and 10 turtles, all driven in circles at 10 Hz (so the
canvas changes at every update).

The browser is a WebSocket client in this process (aiohttp), the protocol the page speaks;
latency is its arrival time less the frame's header stamp, which turtlesim sets just before
it encodes the PNG (same machine, same clock): encode + DDS + viewer + WebSocket. The
baseline is the same run with the viewer up but no tab open: turtlesim then publishes (and
encodes) nothing. CPU is user + system time over the measured window, one core = 100 %.

Under load: 20 tabs watching a 1 kHz topic and the canvas of 10 driven turtles, and one tab
stalled (its socket never read): what each tab gets, the viewer's CPU and resident memory at
the start and end of the window (frames are dropped, not queued: it must not grow).
"""

from __future__ import annotations

import asyncio
import base64
import json
import os
import re
import socket
import threading
import time

import aiohttp
import rclpy
from turtlesim.msg import Pose

from benchmarks.common import Row, fmt_ms, p50, p99, python, smoke, start, stop, wait_for_lines
from benchmarks.turtlesim import HEADLESS, Bench, _cpu_seconds
from benchmarks.websocket import FrameReader

CANVAS = "/turtlesim/_canvas/compressed"
LINK = r"http://\S+"  # the viewer prints where it listens, with its token


def _ws_url(link: str) -> str:
    """The viewer's WebSocket, with the token of the link it printed."""
    page, _, query = link.partition("?")
    return f"{page}ws?{query}"


FAST = "/fast"  # the 1 kHz topic of the load test
TABS = smoke(20, 2)


def _rss_mib(pid: int) -> float:
    with open(f"/proc/{pid}/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    raise RuntimeError(f"no VmRSS for pid {pid}")


def _stalled_tab(url: str) -> socket.socket:
    """A tab that opens the WebSocket (url) and then never reads: its socket's buffers fill."""
    host, port, path = re.match(r"http://([^:/]+):(\d+)(/\S*)", url).groups()
    sock = socket.create_connection((host, int(port)))
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    key = base64.b64encode(os.urandom(16)).decode()
    sock.sendall(
        f"GET {path} HTTP/1.1\r\nHost: {host}:{port}\r\nUpgrade: websocket\r\n"
        f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n"
        "Sec-WebSocket-Version: 13\r\n\r\n".encode()
    )
    if b" 101 " not in sock.recv(1024):
        raise RuntimeError("the viewer refused the stalled tab's WebSocket")
    return sock


class Tabs(threading.Thread):
    """TABS tabs in one event loop, each watching FAST: what each gets."""

    def __init__(self, url: str) -> None:
        super().__init__(daemon=True)
        self.url = url
        self.topic = [0] * TABS
        self.frames = [0] * TABS
        self.stop = threading.Event()
        self.error: BaseException | None = None

    def run(self) -> None:
        try:
            asyncio.run(self._all())
        except BaseException as error:
            self.error = error

    async def _all(self) -> None:
        async with aiohttp.ClientSession() as client:
            await asyncio.gather(*(self._one(client, i) for i in range(TABS)))

    async def _one(self, client: aiohttp.ClientSession, i: int) -> None:
        async with client.ws_connect(self.url) as ws:
            await ws.send_str(json.dumps({"watch": FAST}))
            while not self.stop.is_set():
                try:
                    message = await ws.receive(timeout=0.2)
                except asyncio.TimeoutError:
                    continue
                if message.type == aiohttp.WSMsgType.BINARY:
                    self.frames[i] += 1
                elif message.type == aiohttp.WSMsgType.TEXT and '"type": "topic"' in message.data:
                    self.topic[i] += 1


class Tab(FrameReader):
    """A browser tab's WebSocket in a thread of its own: the latency of every canvas frame."""

    def __init__(self, url: str) -> None:
        super().__init__(url)
        self.arrivals: list[float] = []

    def on_frame(self, header: dict, now: float) -> None:
        if header["topic"] == CANVAS:
            self.latencies.append(now - header["stamp"])
            self.arrivals.append(time.monotonic())


def _measure(bench: Bench, pids: list[int], seconds: float) -> list[float]:
    """CPU share of each process over the next seconds (the bench keeps driving)."""
    before, wall = [_cpu_seconds(pid) for pid in pids], time.monotonic()
    bench.spin_for(seconds)
    wall = time.monotonic() - wall
    return [(_cpu_seconds(pid) - b) / wall for pid, b in zip(pids, before, strict=True)]


def _run(turtles: int, seconds: float) -> dict:
    sim = start(python("-m", "ros_tutorials_turtlesim.turtlesim_node"), env=HEADLESS)
    viewer = start(python("-m", "ros_tutorials_web.viewer", "--port", "0"))
    context = rclpy.Context()
    rclpy.init(context=context)
    bench = Bench(context)
    try:
        if not wait_for_lines(sim, lambda line: "Spawning turtle [turtle1]" in line, 60):
            raise RuntimeError("turtlesim did not start")
        link: list[str] = []
        if not wait_for_lines(viewer, lambda line: link.extend(re.findall(LINK, line)) or link, 60):
            raise RuntimeError("the viewer did not start")
        for proc in (sim, viewer):  # their further lines are not needed; the pipes must not fill
            threading.Thread(target=proc.stdout.read, daemon=True).start()
        bench.drive(bench.spawn(turtles))
        bench.spin_for(2.0)
        idle = _measure(bench, [sim.pid, viewer.pid], seconds)
        tab = Tab(_ws_url(link[0]))
        tab.start()
        bench.spin_until(lambda: len(tab.arrivals) > 5 or tab.error is not None)
        if tab.error is not None:
            raise tab.error
        tab.latencies.clear()
        first = len(tab.arrivals)
        watched = _measure(bench, [sim.pid, viewer.pid], seconds)
        frames = tab.arrivals[first:]
        tab.stop.set()
        tab.join(5)
        rate = (len(frames) - 1) / (frames[-1] - frames[0]) if len(frames) > 1 else 0.0
        return {"idle": idle, "watched": watched, "latency": tab.latencies, "rate": rate}
    finally:
        bench.close()
        context.try_shutdown()
        stop(viewer)
        stop(sim)


def viewer_figures(seconds: float = smoke(10.0, 1.0)) -> list[Row]:
    rows = []
    for turtles in (1, 10):
        got = _run(turtles, seconds)
        label = f"{turtles} turtle{'s' if turtles > 1 else ''} driven"
        latency = got["latency"]
        rows += [
            Row(
                f"web viewer: canvas frame draw -> WebSocket tab, median / p99, {label}",
                f"{fmt_ms(p50(latency))} / {fmt_ms(p99(latency))}",
                target="p99 under 100 ms",
                met=p99(latency) < 0.1,
            ),
            Row(
                f"web viewer: canvas frames a second at the tab, {label}",
                f"{got['rate']:.1f}",
                "turtlesim sends at most 20",
                target="at least 10",
                met=got["rate"] >= 10,
            ),
            Row(
                f"turtlesim CPU with a viewer tab open, {label}",
                f"{got['watched'][0] * 100:.1f} %",
                f"{got['idle'][0] * 100:.1f} % (viewer up, no tab)",
                got["watched"][0] / got["idle"][0] if got["idle"][0] else None,
            ),
            Row(
                f"web viewer CPU with one tab open, {label}",
                f"{got['watched'][1] * 100:.1f} %",
                f"{got['idle'][1] * 100:.1f} % (no tab)",
                got["watched"][1] / got["idle"][1] if got["idle"][1] else None,
            ),
        ]
    return rows


def load(seconds: float = smoke(10.0, 1.0)) -> list[Row]:
    sim = start(python("-m", "ros_tutorials_turtlesim.turtlesim_node"), env=HEADLESS)
    viewer = start(python("-m", "ros_tutorials_web.viewer", "--port", "0"))
    context = rclpy.Context()
    rclpy.init(context=context)
    bench = Bench(context)
    stalled = None
    try:
        if not wait_for_lines(sim, lambda line: "Spawning turtle [turtle1]" in line, 60):
            raise RuntimeError("turtlesim did not start")
        link: list[str] = []
        if not wait_for_lines(viewer, lambda line: link.extend(re.findall(LINK, line)) or link, 60):
            raise RuntimeError("the viewer did not start")
        for proc in (sim, viewer):
            threading.Thread(target=proc.stdout.read, daemon=True).start()
        bench.drive(bench.spawn(10))
        fast = bench.node.create_publisher(Pose, FAST, 10)
        published = [0]

        def publish() -> None:
            fast.publish(Pose(x=float(published[0] % 100)))
            published[0] += 1

        bench.node.create_timer(0.001, publish)
        tabs = Tabs(_ws_url(link[0]))
        tabs.start()
        stalled = _stalled_tab(_ws_url(link[0]))
        bench.spin_until(lambda: min(tabs.topic) > 5 or tabs.error is not None)
        if tabs.error is not None:
            raise tabs.error
        bench.spin_for(2.0)
        rss_start, sent, got, frames = (
            _rss_mib(viewer.pid),
            published[0],
            sum(tabs.topic),
            sum(tabs.frames),
        )
        sim_cpu, viewer_cpu = _measure(bench, [sim.pid, viewer.pid], seconds)
        rss_end = _rss_mib(viewer.pid)
        rate = (published[0] - sent) / seconds
        per_tab = (sum(tabs.topic) - got) / TABS / seconds
        frames_per_tab = (sum(tabs.frames) - frames) / TABS / seconds
        tabs.stop.set()
        tabs.join(5)
    finally:
        if stalled is not None:
            stalled.close()
        bench.close()
        context.try_shutdown()
        stop(viewer)
        stop(sim)
    where = f"{TABS} tabs on a {rate:.0f} Hz topic + 10 driven turtles, 1 tab stalled"
    return [
        Row(
            f"web viewer under load ({where}): topic messages / canvas frames a second per tab",
            f"{per_tab:.1f} / {frames_per_tab:.1f}",
            f"{rate:.0f} published a second",
            target="topic sampled at <= 30, frames >= 10",
            met=per_tab <= 31 and frames_per_tab >= 10,
        ),
        Row(
            f"web viewer under load ({where}): viewer CPU / turtlesim CPU",
            f"{viewer_cpu * 100:.1f} % / {sim_cpu * 100:.1f} %",
        ),
        Row(
            f"web viewer under load ({where}): viewer memory (RSS), start -> {seconds:g} s later",
            f"{rss_start:.0f} -> {rss_end:.0f} MiB",
            target="grows less than 10 MiB",
            met=rss_end - rss_start < 10,
        ),
    ]
