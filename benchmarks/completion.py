"""TAB completion's answer time (ros_tutorials_common/completion.py, ros2cmd/completion.py):
from the shell starting the command with argcomplete's protocol to the command's exit, for a
verb, a live topic through the daemon and a type from the ament index; beside a bare Python
and a bare `import argcomplete`. Target: each under the budget, 150 ms (beyond it a completion
answers nothing)."""

from __future__ import annotations

import os
import resource
import subprocess
import tempfile
import time

from benchmarks.common import Row, fmt_ms, p50, python, smoke, start, stop
from benchmarks.daemon import _bytecode_kept
from benchmarks.graph import BIN
from ros2cmd.daemon import client as daemon
from ros_tutorials_common.completion import BUDGET, COMPLETION_BUDGET_VARIABLE

PUBLISHER = """
import rclpy
from geometry_msgs.msg import Twist
rclpy.init()
node = rclpy.create_node("completion_bench")
node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
print("ready", flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""


def _complete(line: str) -> tuple[float, float, list[str]]:
    """Seconds from start to exit of the command completing LINE, its CPU seconds, and what
    it offered. The budget is lifted so that a slow answer is timed, not cut."""
    env = dict(os.environ)
    env.pop(daemon.NO_DAEMON_VARIABLE, None)
    env.update(
        _ARGCOMPLETE="1",
        _ARGCOMPLETE_IFS="\n",
        COMP_LINE=line,
        COMP_POINT=str(len(line)),
        **{COMPLETION_BUDGET_VARIABLE: "30"},
    )
    with tempfile.NamedTemporaryFile("r") as answer:
        env["_ARGCOMPLETE_STDOUT_FILENAME"] = answer.name
        before = _children_cpu()
        began = time.monotonic()
        subprocess.run(
            [str(BIN / line.split()[0])], env=env, capture_output=True, timeout=60, check=True
        )
        seconds = time.monotonic() - began
        return seconds, _children_cpu() - before, answer.read().split()


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _median(line: str, runs: int) -> tuple[float, float, list[str]]:
    samples, cpu, offered = [], [], []
    for _ in range(runs):
        seconds, used, offered = _complete(line)
        samples.append(seconds)
        cpu.append(used)
    return p50(samples), p50(cpu), offered


def _bare(args: list[str], runs: int) -> float:
    samples = []
    for _ in range(runs):
        began = time.monotonic()
        subprocess.run(args, capture_output=True, timeout=60, check=True)
        samples.append(time.monotonic() - began)
    return p50(samples)


def answer_times(runs: int = smoke(20, 1)) -> list[Row]:
    """p50 of RUNS completions each: a verb, a live topic (a publisher running, the daemon
    started and caught up), a type; the commands keep their bytecode, as in a learner's
    shell (benchmarks/daemon.py)."""
    with _bytecode_kept():
        return _answer_times(runs)


def _answer_times(runs: int) -> list[Row]:
    bare = _bare(python("-c", "pass"), runs)
    argcomplete = _bare(python("-c", "import argcomplete"), runs)
    base = f"{fmt_ms(bare)} (`python -c pass`), {fmt_ms(argcomplete)} (`import argcomplete`)"
    publisher = start(python("-c", PUBLISHER))
    env = dict(os.environ)
    env.pop(daemon.NO_DAEMON_VARIABLE, None)
    subprocess.run([str(BIN / "ros2"), "daemon", "start"], capture_output=True, timeout=60, env=env)
    try:
        deadline = time.monotonic() + 30
        while "/turtle1/cmd_vel" not in _complete("ros2 topic echo /tur")[2]:
            if time.monotonic() > deadline:
                raise RuntimeError("the daemon did not show /turtle1/cmd_vel within 30 s")
            time.sleep(0.1)
        rows = []
        for what, line, expected in (
            ("a verb", "ros2 to", "topic"),
            ("a live topic, through the daemon", "ros2 topic echo /tur", "/turtle1/cmd_vel"),
            (
                "a type, from the ament index",
                "ros2 interface show geometry_msgs/msg/Tw",
                "geometry_msgs/msg/Twist",
            ),
        ):
            seconds, cpu, offered = _median(line, runs)
            if expected not in offered:
                raise RuntimeError(f"{line!r} offered {offered}, not {expected}")
            rows.append(
                Row(
                    f"TAB completion, {what} (`{line}<TAB>`), median of {runs} (CPU)",
                    f"{fmt_ms(seconds)} ({fmt_ms(cpu)} CPU)",
                    base,
                    seconds / bare,
                    f"< {BUDGET * 1e3:.0f} ms",
                    seconds < BUDGET,
                )
            )
        return rows
    finally:
        daemon.stop_quietly()
        stop(publisher)
