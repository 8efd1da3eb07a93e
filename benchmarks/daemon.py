"""Daemon figures (ros2cmd/daemon.py): how fast `ros2` starts, beside a bare Python and a bare
`import rclpy`; and `ros2 node list` with and without the daemon at union.launch + 20 nodes
(24 nodes), beside the time discovery itself needs (a bare rclpy node waiting until it sees
all 24)."""

from __future__ import annotations

import subprocess
import time

from benchmarks.common import Row, fmt_ms, p50, p99, python, stop
from benchmarks.graph import BARE, BIN, EXPECTED_NODES, EXPECTED_TOPICS, _running, _timed
from ros2cmd import daemon


def _median_run(args: list[str], runs: int, env: dict[str, str] | None = None) -> float:
    seconds = []
    for _ in range(runs):
        began = time.monotonic()
        subprocess.run(args, capture_output=True, timeout=60, env=env)
        seconds.append(time.monotonic() - began)
    return p50(seconds)


def startup(runs: int = 10) -> list[Row]:
    """Start to exit with nothing running: `ros2 -h`; `ros2 topic list` through a running
    daemon and without it."""
    bare = _median_run(python("-c", "pass"), runs)
    rclpy = _median_run(python("-c", "import rclpy"), runs)
    ros2 = str(BIN / "ros2")
    help_time = _median_run([ros2, "-h"], runs)
    subprocess.run([ros2, "daemon", "start"], capture_output=True, timeout=60)
    try:
        through = _median_run([ros2, "topic", "list"], runs)
    finally:
        daemon.stop_quietly()
    direct = _median_run([ros2, "topic", "list", "--no-daemon"], runs)
    base = f"{fmt_ms(bare)} (`python -c pass`), {fmt_ms(rclpy)} (`import rclpy`)"
    return [
        Row(f"`ros2 -h`, median of {runs}", fmt_ms(help_time), base, help_time / rclpy),
        Row(
            f"`ros2 topic list`, nothing running, daemon running, median of {runs}",
            fmt_ms(through),
            base,
            through / rclpy,
        ),
        Row(
            f"`ros2 topic list --no-daemon`, nothing running, median of {runs}",
            fmt_ms(direct),
            base,
            direct / rclpy,
        ),
    ]


def lists(runs: int = 10) -> list[Row]:
    """`ros2 node list` at 24 nodes: through the daemon (started and caught up first), and
    discovering for itself, interleaved; each checked complete."""
    procs = _running()
    ros2 = str(BIN / "ros2")
    try:
        bare = python("-c", BARE, ",".join(EXPECTED_NODES), ",".join(EXPECTED_TOPICS))
        _timed(bare)  # everything is up once a bare node sees it all
        subprocess.run([ros2, "daemon", "start"], capture_output=True, timeout=60)
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:  # caught up: it answers complete
            answer = daemon.ask_graph()
            if answer is not None and answer.node_names() == EXPECTED_NODES:
                break
            time.sleep(0.1)
        samples: dict[str, list[float]] = {"daemon": [], "direct": [], "bare": []}
        complete = {"daemon": 0, "direct": 0}
        declined = 0
        for _ in range(runs):
            for way, extra in (("daemon", []), ("direct", ["--no-daemon"])):
                seconds, out = _timed([ros2, "node", "list", *extra])
                samples[way].append(seconds)
                complete[way] += out.split() == EXPECTED_NODES
            declined += daemon.ask_graph() is None
            samples["bare"].append(_timed(bare)[0])
    finally:
        daemon.stop_quietly()
        for proc in procs:
            stop(proc)
    base = samples["bare"]
    rows = []
    for way, what in (("daemon", "through the daemon"), ("direct", "--no-daemon")):
        s = samples[way]
        rows.append(
            Row(
                f"`ros2 node list` {what}, {len(EXPECTED_NODES)} nodes, start to exit, "
                f"p50/p99 of {runs} (complete: {complete[way]}/{runs})",
                f"{fmt_ms(p50(s))} / {fmt_ms(p99(s))}",
                f"{fmt_ms(p50(base))} / {fmt_ms(p99(base))} (bare rclpy node seeing all)",
                p50(s) / p50(base),
                "<= 0.5 s, complete every run" if way == "daemon" else "complete every run",
                complete[way] == runs and (way != "daemon" or p99(s) <= 0.5),
            )
        )
    rows.append(Row(f"daemon declined (list fell back), of {runs} asks", str(declined)))
    return rows


__all__ = ["lists", "startup"]
