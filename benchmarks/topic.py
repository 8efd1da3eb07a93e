"""Topic figures (issue item 4 and 5): latency, throughput, loss at 1 kHz, 10 Hz rate accuracy."""

from __future__ import annotations

import itertools
import json
import os
import signal
import subprocess
import time

import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from ros_tutorials_interfaces.msg import MsgTutorial

from benchmarks.common import Row, fmt_us, p50, p99, python, run_worker, smoke, start

QUIET = ["--ros-args", "--log-level", "warn"]


def _worker(*args: str) -> dict:
    return run_worker("benchmarks.topic_worker", *args)


def latency(count: int = smoke(2000, 20), rounds: int = smoke(3, 1)) -> list[Row]:
    """Publish -> subscriber callback, two nodes in one process (as REFERENCE section 3)."""
    samples: dict[str, list[float]] = {"tutorial": [], "quiet": [], "bare": []}
    for _ in range(rounds):  # interleaved, so machine load hits all alike
        samples["tutorial"] += _worker("latency", "tutorial", str(count))["latency"]
        samples["quiet"] += _worker("latency", "tutorial", str(count), *QUIET)["latency"]
        samples["bare"] += _worker("latency", "bare", str(count))["latency"]
    bare = samples["bare"]
    rows = []
    for kind, label in (("tutorial", "book's logging, 6 lines/msg"), ("quiet", "--log-level warn")):
        s = samples[kind]
        rows.append(
            Row(
                f"topic latency p50/p99, tutorial nodes ({label})",
                f"{fmt_us(p50(s))} / {fmt_us(p99(s))}",
                f"{fmt_us(p50(bare))} / {fmt_us(p99(bare))}",
                p50(s) / p50(bare),
            )
        )
    return rows


def _pub_sub(
    kind: str, rate_hz: float, seconds: float, topic: str, *extra: str
) -> tuple[dict, dict]:
    sub = start(
        python("-m", "benchmarks.topic_worker", "subscribe", kind, topic, *extra),
        stderr=subprocess.DEVNULL,
    )
    assert sub.stdout is not None
    sub.stdout.readline()  # {"ready": true}
    sent = _worker("publish", kind, str(rate_hz), str(seconds), topic, *extra)
    os.killpg(sub.pid, signal.SIGINT)
    out, _ = sub.communicate(timeout=60)
    return sent, json.loads(out.strip().splitlines()[-1])


def loss_and_throughput(seconds: float = smoke(5.0, 1.0)) -> list[Row]:
    """Messages lost at 1 kHz, tutorial nodes with the book's logging and without, and bare.

    The book's subscriber logs three lines per message (and the publisher three per send);
    each costs about 0.25 ms in rclpy, so at 1 kHz the subscriber falls behind its queue of
    100 and a loaded machine loses messages. `--log-level warn` switches those lines off.
    """
    rows = []
    results = {}
    runs = {"tutorial": ("tutorial",), "quiet": ("tutorial", *QUIET), "bare": ("bare",)}
    for name, (kind, *extra) in runs.items():
        results[name] = _pub_sub(kind, 1000.0, seconds, f"bench_loss_{name}", *extra)
    b = results["bare"]
    labels = {"tutorial": "book's logging, 3 lines/msg each side", "quiet": "--log-level warn"}
    for name, label in labels.items():
        t = results[name]
        rows.append(
            Row(
                f"loss at 1 kHz for {seconds:.0f} s, queue 100, reliable, tutorial nodes ({label})",
                f"{t[1]['lost']} lost of {t[0]['sent']} ({t[1]['received']} received)",
                f"{b[1]['lost']} lost of {b[0]['sent']} (bare rclpy)",
                None,
                "0 lost",
                t[1]["lost"] == 0 and t[1]["received"] == t[0]["sent"],
            )
        )
    for kind in ("tutorial", "bare"):
        results[kind] = _pub_sub(kind, 0.0, seconds, f"bench_tp_{kind}")
    rate = {k: v[1]["received"] / max(v[1]["span"], 1e-9) for k, v in results.items()}
    rows.append(
        Row(
            "max throughput, publish in a loop (2 processes)",
            f"{rate['tutorial']:.0f} msg/s ({results['tutorial'][1]['lost']} lost)",
            f"{rate['bare']:.0f} msg/s ({results['bare'][1]['lost']} lost)",
            rate["tutorial"] / rate["bare"],
        )
    )
    return rows


def rate_accuracy(seconds: float = smoke(30.0, 2.0)) -> list[Row]:
    """The unmodified tutorial publisher process at 10 Hz, beside a bare rclpy timer at 10 Hz."""
    context = rclpy.Context()
    rclpy.init(context=context)
    node = Node("rate_recorder", context=context)
    stamps: dict[str, list[float]] = {"tutorial": [], "bare": []}

    def recorder(kind: str):
        return lambda msg: stamps[kind].append(msg.stamp.sec + msg.stamp.nanosec * 1e-9)

    node.create_subscription(MsgTutorial, "bench_rate_tutorial", recorder("tutorial"), 100)
    node.create_subscription(MsgTutorial, "bench_rate_bare", recorder("bare"), 100)
    tutorial = start(
        python(
            "-m",
            "ros_tutorials_topic.publisher",
            "--ros-args",
            "-r",
            "ros_tutorial_msg:=bench_rate_tutorial",
        ),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    bare = start(
        python(
            "-m",
            "benchmarks.topic_worker",
            "publish",
            "bare",
            "10",
            str(seconds + 2),
            "bench_rate_bare",
        ),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(node)
    deadline = time.monotonic() + seconds + 30
    while time.monotonic() < deadline and min(len(s) for s in stamps.values()) < seconds * 10 + 1:
        executor.spin_once(timeout_sec=0.1)
    for proc in (tutorial, bare):
        os.killpg(proc.pid, signal.SIGINT)
        proc.wait(30)
    node.destroy_node()
    context.try_shutdown()
    rows = []
    figures = {}
    for kind, s in stamps.items():
        s = s[: int(seconds * 10) + 1]
        if len(s) < 3:
            raise RuntimeError(f"the {kind} publisher sent {len(s)} messages in {seconds:g} s")
        periods = [b - a for a, b in itertools.pairwise(s)]
        mean_rate = len(periods) / (s[-1] - s[0])
        jitter = [abs(p - 0.1) for p in periods]
        figures[kind] = (mean_rate, p99(jitter))
    (t_rate, t_jit), (b_rate, b_jit) = figures["tutorial"], figures["bare"]
    rows.append(
        Row(
            f"publisher rate at 10 Hz over {seconds:.0f} s: mean rate",
            f"{t_rate:.3f} Hz",
            f"{b_rate:.3f} Hz",
            t_rate / b_rate,
            "within 0.5 %",
            abs(t_rate - 10) / 10 <= 0.005,
        )
    )
    rows.append(
        Row(
            "publisher period jitter p99",
            f"{t_jit * 1e3:.2f} ms",
            f"{b_jit * 1e3:.2f} ms",
            t_jit / b_jit if b_jit else None,
            "<= 5 ms",
            t_jit <= 0.005,
        )
    )
    return rows
