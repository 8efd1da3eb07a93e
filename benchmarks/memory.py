"""Peak RSS (VmHWM) of one tutorial node process, and of bare rclpy with one node."""

from __future__ import annotations

import os
import signal
import subprocess

from benchmarks.common import Row, peak_rss_mib, python, start, wait_for_lines

BARE_NODE = (
    "import rclpy, sys\n"
    "rclpy.init()\n"
    "node = rclpy.create_node('bare')\n"
    "print('ready', flush=True)\n"
    "sys.stdin.readline()\n"
)


def _peak_rss(args: list[str], ready: str) -> float:
    proc = start(args, stdin=subprocess.PIPE)
    try:
        if not wait_for_lines(proc, lambda line: ready in line, timeout=60):
            raise RuntimeError(f"{args} never printed {ready!r}")
        return peak_rss_mib(proc.pid)
    finally:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()


def node_memory() -> list[Row]:
    node = _peak_rss(python("-m", "ros_tutorials_topic.publisher"), "send msg = 2")
    bare = _peak_rss(python("-c", BARE_NODE), "ready")
    return [
        Row(
            "peak RSS, tutorial publisher node",
            f"{node:.0f} MiB",
            f"{bare:.0f} MiB (bare rclpy node)",
            node / bare,
        )
    ]
