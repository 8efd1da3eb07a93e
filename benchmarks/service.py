"""Service figure (issue item 3): round trip, tutorial client -> tutorial server, two processes,
beside a bare rclpy client -> bare rclpy server pair."""

from __future__ import annotations

import json
import subprocess

from benchmarks.common import Row, fmt_us, p50, p99, python, start, stop

QUIET = ["--ros-args", "--log-level", "warn"]
SERVERS = {
    "tutorial": python("-m", "ros_tutorials_service.server"),
    "quiet": python("-m", "ros_tutorials_service.server", *QUIET),
    "bare": python("-m", "benchmarks.service_worker", "server"),
}
CLIENTS = {
    "tutorial": ["client", "tutorial"],
    "quiet": ["client", "tutorial"],
    "bare": ["client", "bare"],
}


def _round_trips(kind: str, count: int) -> list[float]:
    server = start(SERVERS[kind], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        args = [*CLIENTS[kind], str(count), *(QUIET if kind == "quiet" else [])]
        out = subprocess.run(
            python("-m", "benchmarks.service_worker", *args),
            capture_output=True,
            text=True,
            timeout=300,
            check=True,
        )
        return json.loads(out.stdout.strip().splitlines()[-1])["round_trip"]
    finally:
        stop(server)


def round_trip(count: int = 2000, rounds: int = 3) -> list[Row]:
    samples: dict[str, list[float]] = {kind: [] for kind in SERVERS}
    for _ in range(rounds):  # interleaved, so machine load hits all alike
        for kind in SERVERS:
            samples[kind] += _round_trips(kind, count)
    bare = samples["bare"]
    rows = []
    for kind, label in (
        ("tutorial", "book's logging, 4 lines/call"),
        ("quiet", "--log-level warn"),
    ):
        s = samples[kind]
        ratio = p50(s) / p50(bare)
        rows.append(
            Row(
                f"service round trip p50/p99, tutorial client+server ({label})",
                f"{fmt_us(p50(s))} / {fmt_us(p99(s))}",
                f"{fmt_us(p50(bare))} / {fmt_us(p99(bare))}",
                ratio,
                "p50 ratio <= 1.2",
                ratio <= 1.2,
            )
        )
    return rows
