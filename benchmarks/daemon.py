"""Command-line figures (issue 39; ros2cmd/cli.py, ros2cmd/daemon/): how fast `ros2` answers
help, the daemon's answers and `ros2 run`, beside a bare Python and a bare `import rclpy` in the
same run; and `ros2 node list` with and without the daemon at union.launch + 20 nodes (24
nodes), beside the time discovery itself needs (a bare rclpy node waiting until it sees all
24)."""

from __future__ import annotations

import contextlib
import os
import subprocess
import time
from collections.abc import Iterator

from benchmarks.common import (
    Row,
    fmt_ms,
    p50,
    p99,
    python,
    smoke,
    start,
    stop,
    wait_for_lines,
)
from benchmarks.graph import BARE, BIN, EXPECTED_NODES, EXPECTED_TOPICS, _running, _timed
from ros2cmd.daemon import client as daemon
from ros_tutorials_common.dds import apply_dds_defaults

HELP_TARGET = 0.100  # s, p50: `ros2 -h`, `ros2 VERB -h`, `ros2 run -h` (issue 39)
DAEMON_TARGET = 0.150  # s, p50: what the daemon answers
RUN_TARGET = 0.060  # s, p50: what `ros2 run` adds before the node's own start
# A few nodes for the daemon's answers: a publisher, a service server, an action server.
NODES = (
    "ros_tutorials_topic.publisher",
    "ros_tutorials_service.server",
    "ros_tutorials_action.server",
)


@contextlib.contextmanager
def _bytecode_kept() -> Iterator[None]:
    """The commands run as in a learner's shell: Python keeps what it compiles (__pycache__).
    Under PYTHONDONTWRITEBYTECODE (some containers set it) every run would compile each
    module changed since the last `make setup` again, and time that instead."""
    saved = os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
    try:
        yield
    finally:
        if saved is not None:
            os.environ["PYTHONDONTWRITEBYTECODE"] = saved


def _interleaved(commands: list[list[str]], runs: int) -> list[list[float]]:
    """Start to exit of each command, `runs` times, the commands taking turns (a change of
    the machine's load hits them alike)."""
    seconds: list[list[float]] = [[] for _ in commands]
    for _ in range(runs):
        for samples, args in zip(seconds, commands, strict=True):
            began = time.monotonic()
            subprocess.run(args, capture_output=True, timeout=60)
            samples.append(time.monotonic() - began)
    return seconds


def _timed_rows(
    commands: list[list[str]], runs: int, what: str, target: float | None = None
) -> list[Row]:
    """A row per command, beside `python -c pass` and `import rclpy` run in turn with them:
    p50 (and the best run, what an idle machine would show), the ratio to `import rclpy`."""
    bare, rclpy, *timed = _interleaved(
        [python("-c", "pass"), python("-c", "import rclpy"), *commands], runs
    )
    base = (
        f"{fmt_ms(p50(bare))} (best {fmt_ms(min(bare))}) `python -c pass`, "
        f"{fmt_ms(p50(rclpy))} (best {fmt_ms(min(rclpy))}) `import rclpy`"
    )
    rows = []
    for command, samples in zip(commands, timed, strict=True):
        shown = " ".join([command[0].rsplit("/", 1)[-1], *command[1:]])
        rows.append(
            Row(
                f"`{shown}`{what}, p50 (best) of {runs}",
                f"{fmt_ms(p50(samples))} ({fmt_ms(min(samples))})",
                base,
                p50(samples) / p50(rclpy),
                "" if target is None else f"<= {fmt_ms(target)}",
                None if target is None else p50(samples) <= target,
            )
        )
    return rows


def _first_lines(commands: list[list[str]], runs: int) -> list[float]:
    """p50 of start to the first line each program prints (a node's first log line), the
    commands taking turns so that the machine's load changes hit them alike. Each starts with
    the project's DDS defaults, which `ros2 run` gives the node it starts (an activated
    environment gives them to `python -m` too)."""
    seconds: list[list[float]] = [[] for _ in commands]
    for _ in range(runs):
        for samples, args in zip(seconds, commands, strict=True):
            began = time.monotonic()
            proc = start(args, env=dict(apply_dds_defaults(dict(os.environ))))
            try:
                if not wait_for_lines(proc, lambda _line: True, timeout=60):
                    raise RuntimeError(f"{' '.join(args)} printed nothing")
                samples.append(time.monotonic() - began)
            finally:
                stop(proc)
    return [p50(samples) for samples in seconds]


def _complete_answer(wanted: str, timeout: float = 30.0) -> None:
    """Wait until the daemon answers complete with the node `wanted` in it."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        answer = daemon.ask_graph()
        if answer is not None and wanted in answer.node_names():
            return
        time.sleep(0.1)
    raise RuntimeError(f"the daemon did not answer with {wanted} within {timeout:g} s")


def startup(runs: int = smoke(10, 1)) -> list[Row]:
    """Start to exit: help, with nothing running; the daemon's answers with three nodes up
    (a daemon running), and `topic list --no-daemon` beside them; what `ros2 run` and
    `rosrun` add to a node's start (its first output line through them, minus through
    `python -m MODULE`)."""
    with _bytecode_kept():
        return _startup(runs)


def _startup(runs: int) -> list[Row]:
    ros2 = str(BIN / "ros2")
    help_commands = [[ros2, "-h"], [ros2, "topic", "-h"], [ros2, "run", "-h"]]
    rows = _timed_rows([*help_commands, [str(BIN / "rostopic"), "-h"]], runs, "", HELP_TARGET)
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    procs = [start(python("-m", module), **quiet) for module in NODES]
    subprocess.run([ros2, "daemon", "start"], capture_output=True, timeout=60)
    try:
        _complete_answer("/action_server")
        answered = [
            [ros2, "node", "list"],
            [ros2, "topic", "list"],
            [ros2, "service", "list"],
            [ros2, "action", "list"],
            [ros2, "node", "info", "/topic_publisher"],
            [ros2, "topic", "info", "/ros_tutorial_msg"],
            [ros2, "topic", "type", "/ros_tutorial_msg"],
        ]
        rows += _timed_rows(answered, runs, ", through the daemon, 3 nodes up", DAEMON_TARGET)
        rows += _timed_rows(
            [[ros2, "interface", "list"]], runs, " (the ament index)", DAEMON_TARGET
        )
        declined = sum(daemon.ask_graph() is None for _ in range(runs))
        rows.append(Row(f"daemon declined, of {runs} asks (3 nodes up)", str(declined)))
    finally:
        daemon.stop_quietly()
        for proc in procs:
            stop(proc)
    rows += _timed_rows([[ros2, "topic", "list", "--no-daemon"]], runs, ", nothing running")
    # ros2 run's own part, steady: it looks the executable up, then `true` replaces it.
    rows += _timed_rows(
        [[ros2, "run", "--prefix", "true", "ros_tutorials_topic", "topic_publisher"]], runs, ""
    )
    launchers = [
        [ros2, "run", "ros_tutorials_topic", "topic_publisher"],
        [str(BIN / "rosrun"), "ros_tutorials_topic", "topic_publisher"],
    ]
    module, *through = _first_lines(
        [python("-m", "ros_tutorials_topic.publisher"), *launchers], runs
    )
    for command, took in zip(launchers, through, strict=True):
        added = took - module
        shown = " ".join([command[0].rsplit("/", 1)[-1], *command[1:]])
        rows.append(
            Row(
                f"`{shown}`: added to the node's first output line, p50 of {runs} each",
                fmt_ms(added),
                f"{fmt_ms(module)} (`python -m ros_tutorials_topic.publisher`)",
                None,
                f"<= {fmt_ms(RUN_TARGET)}",
                added <= RUN_TARGET,
            )
        )
    return rows


def lists(runs: int = smoke(10, 1)) -> list[Row]:
    """`ros2 node list` at 24 nodes: through the daemon (started and caught up first), and
    discovering for itself, interleaved; each checked complete."""
    with _bytecode_kept():
        return _lists(runs)


def _lists(runs: int) -> list[Row]:
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
