"""Service figure (issue item 3): round trip, tutorial client -> tutorial server, two processes,
beside a bare rclpy client -> bare rclpy server pair measured the same way: the same executor
(the server's rclpy.spin, the client's spin_once loop), default service QoS, the same number
of calls after the same warm-up, one process each side, the same ROS arguments for the
quiet comparison. The bare pair logs nothing, so its log level does not matter.

Rounds are short and many, and each round runs the kinds in another order, so that the load
of a shared machine falls on all alike. Beside the round trip (wall time, which the load
moves), each kind's CPU time per call, client and server together: what the nodes cost,
which the load hardly moves."""

from __future__ import annotations

import subprocess

from benchmarks.common import Row, fmt_us, p50, p99, python, run_worker, smoke, start, stop

QUIET = ["--ros-args", "--log-level", "warn"]
SERVERS = {
    "tutorial": python("-m", "ros_tutorials_service.server"),
    "quiet": python("-m", "ros_tutorials_service.server", *QUIET),
    "bare": python("-m", "benchmarks.service_worker", "server", *QUIET),
}
CLIENTS = {
    "tutorial": (["client", "tutorial"], []),
    "quiet": (["client", "tutorial"], QUIET),
    "bare": (["client", "bare"], QUIET),
}
TARGET = 1.15  # issue 39: the quiet tutorial nodes within 1.15 x bare rclpy


def _round(kind: str, count: int) -> dict:
    server = start(SERVERS[kind], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        verb, ros = CLIENTS[kind]
        return run_worker("benchmarks.service_worker", *verb, str(count), str(server.pid), *ros)
    finally:
        stop(server)


def round_trip(count: int = smoke(1000, 20), rounds: int = smoke(6, 1)) -> list[Row]:
    samples: dict[str, list[float]] = {kind: [] for kind in SERVERS}
    cpu: dict[str, list[float]] = {kind: [] for kind in SERVERS}
    kinds = list(SERVERS)
    for turn in range(rounds):
        for kind in kinds[turn % len(kinds) :] + kinds[: turn % len(kinds)]:
            result = _round(kind, count)
            samples[kind] += result["round_trip"]
            cpu[kind].append(result["client_cpu"] + result["server_cpu"])
    bare, bare_cpu = samples["bare"], p50(cpu["bare"])
    rows = []
    for kind, label in (
        ("tutorial", "book's logging, 4 lines/call"),
        ("quiet", "--log-level warn"),
    ):
        s = samples[kind]
        ratio = p50(s) / p50(bare)
        rows.append(
            Row(
                f"service round trip p50/p99, tutorial client+server ({label}), "
                f"{rounds} rounds of {count}",
                f"{fmt_us(p50(s))} / {fmt_us(p99(s))}",
                f"{fmt_us(p50(bare))} / {fmt_us(p99(bare))}",
                ratio,
                f"p50 ratio <= {TARGET}" if kind == "quiet" else "",
                ratio <= TARGET if kind == "quiet" else None,
            )
        )
        rows.append(
            Row(
                f"service CPU per call, client + server processes, median of rounds ({label})",
                fmt_us(p50(cpu[kind])),
                f"{fmt_us(bare_cpu)} (bare rclpy)",
                p50(cpu[kind]) / bare_cpu,
            )
        )
    return rows
