"""Bags: record under load without loss, `info` on a 1 GB bag, play timing.

- record: `rosbag record` of 1 kHz MsgTutorial + 30 Hz 1 MB sensor_msgs/Image for 10 s;
  messages in the bag against the publisher's counts; the recorder's CPU and peak RSS beside
  a bare rclpy process with the same raw subscriptions that only counts.
- many topics: `rosbag record` of 50 topics at 1 kHz each (small messages) and, in the same
  run, a bare rclpy subscriber per topic: what each lost, and what the recorder accounted for;
  sent by one publisher process, then by two (each half of the topics).
- info: `rosbag info` (the whole command, process start to exit) on a 1 GB bag, beside
  reading the same summary with the mcap package alone, in-process.
- play: `rosbag play` of the recorded bag into a subscriber; the error of each arrival
  against the recorded timestamps (both relative to the first message).
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from mcap.reader import make_reader

from benchmarks.common import (
    Row,
    p50,
    p99,
    peak_rss_mib,
    python,
    smoke,
    start,
    stop,
    wait_for_lines,
)
from rosbag2.metadata import TopicInfo
from rosbag2.reader import BagReader
from rosbag2.writer import BagWriter

SECONDS = smoke(10.0, 1.0)
ROSBAG = str(Path(sys.executable).parent / "rosbag")  # the installed command, as a user runs it
TICKS = os.sysconf("SC_CLK_TCK")


def _cpu_seconds(pid: int) -> float:
    with open(f"/proc/{pid}/stat") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / TICKS  # utime + stime


def _json_result(proc: subprocess.Popen, timeout: float = 120) -> dict:
    out, _ = proc.communicate(timeout=timeout)
    try:
        return json.loads(out.strip().splitlines()[-1])
    except (IndexError, ValueError):
        tail = "\n".join(out.strip().splitlines()[-15:])
        raise RuntimeError(f"{proc.args} ended without its result; it printed:\n{tail}") from None


def _load(subscriber: list[str], ready: str) -> dict:
    """Run the publisher against one subscribing process; its counts, CPU and RSS."""
    sink = start(subscriber)
    try:
        if not wait_for_lines(sink, lambda line: ready in line, timeout=60):
            raise RuntimeError(f"{subscriber} never printed {ready!r}")
        publisher = start(python("-m", "benchmarks.bag_worker", "publish", str(SECONDS)))
        wait_for_lines(publisher, lambda line: "publishing" in line, timeout=120)
        cpu_start = _cpu_seconds(sink.pid)
        sent = _json_result(publisher, timeout=SECONDS + 120)
        time.sleep(0.5)  # the last messages reach the subscriber
        cpu = _cpu_seconds(sink.pid) - cpu_start  # CPU seconds spent while the load ran
        rss = peak_rss_mib(sink.pid)
        os.killpg(sink.pid, signal.SIGINT)
        out, _ = sink.communicate(timeout=60)
        return {"sent": sent, "cpu": cpu, "rss": rss, "output": out}
    finally:
        stop(sink)


def record_and_play() -> list[Row]:
    folder = Path(tempfile.mkdtemp(prefix="bag_bench_")) / "load"
    try:
        recorded = _load(
            [ROSBAG, "record", "/bench_tutorial", "/bench_image", "-O", str(folder)],
            "Recording to",
        )  # fmt: skip
        bare = _load(python("-m", "benchmarks.bag_worker", "bare"), "Subscribed")
        bare_counts = json.loads(bare["output"].strip().splitlines()[-1])
        with BagReader(folder) as reader:
            topics = reader.bag.topics
            in_bag = {
                "tutorial": topics["/bench_tutorial"].message_count,
                "image": topics["/bench_image"].message_count,
            }
            accounted = sum(reader.bag.lost.values())  # what the recorder says it lost
        sent = recorded["sent"]
        # CPU per message taken: what each costs, whatever share of the CPU it was given.
        recorder_cpu = recorded["cpu"] / max(1, sum(in_bag.values())) * 1000
        bare_cpu = bare["cpu"] / max(1, bare_counts["tutorial"] + bare_counts["image"]) * 1000
        lost = (sent["tutorial"] - in_bag["tutorial"]) + (sent["image"] - in_bag["image"])
        bare_lost = (bare["sent"]["tutorial"] - bare_counts["tutorial"]) + (
            bare["sent"]["image"] - bare_counts["image"]
        )
        rows = [
            Row(
                "record 1 kHz MsgTutorial + 30 Hz 1 MB Image, 10 s: lost",
                f"{lost} of {sent['tutorial']} + {sent['image']}",
                f"{bare_lost} of {bare['sent']['tutorial']} + {bare['sent']['image']} "
                "(bare rclpy raw subscriber)",
                target="0 lost",
                met=lost == 0,
            ),
            Row(
                "record: loss the recorder accounted for (rosbag info's 'lost:')",
                f"{accounted} of {lost} lost",
                "(the publisher's count minus the bag's)",
                target="all of it",
                met=accounted == lost,
            ),
            Row(
                "recorder CPU per 1000 messages (1 kHz + 30 Hz 1 MB mix)",
                f"{recorder_cpu * 1e3:.0f} ms",
                f"{bare_cpu * 1e3:.0f} ms (bare subscriber, writes nothing)",
                recorder_cpu / bare_cpu if bare_cpu else None,
            ),
            Row(
                "recorder peak RSS",
                f"{recorded['rss']:.0f} MiB",
                f"{bare['rss']:.0f} MiB (bare subscriber)",
                recorded["rss"] / bare["rss"],
            ),
        ]
        return rows + _play_timing(folder)
    finally:
        shutil.rmtree(folder.parent, ignore_errors=True)


def _play_timing(folder: Path) -> list[Row]:
    with BagReader(folder) as reader:
        recorded = [(m.data[:16].hex(), m.log_time) for m in reader.messages()]
    listener = start(python("-m", "benchmarks.bag_worker", "listen", str(len(recorded))))
    try:
        wait_for_lines(listener, lambda line: "ready" in line, timeout=60)
        player = start(
            [ROSBAG, "play", str(folder), "--wait-for-subscribers", "--timeout", "60"],
        )  # fmt: skip
        player.communicate(timeout=SECONDS * 3 + 120)
        time.sleep(1.0)  # the last messages reach the listener
        if listener.poll() is None:
            os.killpg(listener.pid, signal.SIGINT)
        arrivals = _json_result(listener, timeout=60)["arrivals"]
    finally:
        stop(listener)
    # Pair each arrival with its recorded message by the message's first bytes (its stamp).
    log_times = {key: log_time for key, log_time in recorded}
    pairs = [(log_times[key], arrival) for key, arrival in arrivals if key in log_times]
    first_log, first_arrival = min(pairs)
    errors = [abs((arrival - first_arrival) - (log - first_log)) / 1e9 for log, arrival in pairs]
    return [
        Row(
            "play timing error vs recorded timestamps, p50/p99",
            f"{p50(errors) * 1e3:.2f} ms / {p99(errors) * 1e3:.2f} ms",
            f"{len(errors)} of {len(recorded)} messages arrived",
            target="",
        )
    ]


def info_on_a_large_bag() -> list[Row]:
    """A 1 GiB bag (1024 messages of 1 MiB) written directly, then `rosbag info` on it."""
    folder = Path(tempfile.mkdtemp(prefix="bag_bench_")) / "large"
    try:
        writer = BagWriter(folder)
        writer.add_topic(TopicInfo("/large", "sensor_msgs/msg/Image"), "", "ros2msg")
        payload = bytes(1024 * 1024)
        for i in range(smoke(1024, 8)):
            writer.write("/large", payload, 1_700_000_000_000_000_000 + i * 33_000_000, 0)
        writer.close()
        size = sum(p.stat().st_size for p in folder.iterdir())
        command = [ROSBAG, "info", str(folder)]
        times, cpu_times = [], []
        for _ in range(smoke(5, 1)):
            before = os.times()
            begin = time.monotonic()
            subprocess.run(command, check=True, capture_output=True, timeout=60)
            times.append(time.monotonic() - begin)
            after = os.times()
            cpu_times.append(
                after.children_user
                - before.children_user
                + after.children_system
                - before.children_system
            )
        summary_times = []
        for _ in range(smoke(5, 1)):
            begin = time.monotonic()
            with open(folder / "large_0.mcap", "rb") as stream:
                make_reader(stream).get_summary()
            summary_times.append(time.monotonic() - begin)
        return [
            Row(
                f"`rosbag info` on a {size / 2**30:.2f} GiB bag, start to exit, p50/max (CPU p50)",
                f"{p50(times):.2f} s / {max(times):.2f} s ({p50(cpu_times):.2f} s CPU)",
                f"{p50(summary_times) * 1e3:.1f} ms (mcap summary read alone, in-process)",
                target="< 0.5 s",
                met=max(times) < 0.5,
            )
        ]
    finally:
        shutil.rmtree(folder.parent, ignore_errors=True)


MANY_TOPICS = smoke(50, 5)


def many_topics(publishers: int = 1) -> list[Row]:
    """50 x 1 kHz into the recorder and into a bare subscriber per topic, at the same time,
    from PUBLISHERS processes (one Python process cannot send 50 000 messages a second)."""
    folder = Path(tempfile.mkdtemp(prefix="bag_bench_")) / "many"
    names = [f"/bench_many_{i}" for i in range(MANY_TOPICS)]
    recorder = start([ROSBAG, "record", *names, "-O", str(folder)])
    bare = start(python("-m", "benchmarks.bag_worker", "bare_many", str(MANY_TOPICS)))
    senders: list[subprocess.Popen] = []
    try:
        for proc, ready in ((recorder, "Recording to"), (bare, "Subscribed")):
            if not wait_for_lines(proc, lambda line, r=ready: r in line, timeout=60):
                raise RuntimeError(f"{proc.args[:3]} never printed {ready!r}")
        senders = [
            start(
                python(
                    "-m",
                    "benchmarks.bag_worker",
                    "publish_many",
                    str(MANY_TOPICS),
                    str(SECONDS),
                    str(part),
                    str(publishers),
                )
            )
            for part in range(publishers)
        ]
        results = [_json_result(sender, timeout=SECONDS + 180) for sender in senders]
        time.sleep(1.0)  # the last messages reach the subscribers
        for proc in (recorder, bare):
            os.killpg(proc.pid, signal.SIGINT)
        recorder.communicate(timeout=120)
        bare_received = _json_result(bare)["received"]
        with BagReader(folder) as reader:
            in_bag = sum(topic.message_count for topic in reader.bag.topics.values())
            accounted = sum(reader.bag.lost.values())
    finally:
        for proc in (recorder, bare, *senders):
            stop(proc)
        shutil.rmtree(folder.parent, ignore_errors=True)
    sent = sum(result["sent"] for result in results)
    rate = sent / max(result["seconds"] for result in results) / MANY_TOPICS
    lost, bare_lost = sent - in_bag, sent - bare_received
    processes = f"{publishers} publisher process{'es' if publishers > 1 else ''}"
    return [
        Row(
            f"record {MANY_TOPICS} topics x 1 kHz, {SECONDS:g} s, {processes} "
            f"(sent at {rate:.0f} Hz per topic): lost",
            f"{lost} of {sent} ({lost / sent:.1%})",
            f"{bare_lost} ({bare_lost / sent:.1%}, bare rclpy subscriber per topic, same run)",
            target="no more than the bare subscriber",
            met=lost <= bare_lost,
        ),
        Row(
            f"record {MANY_TOPICS} x 1 kHz, {processes}: loss the recorder accounted for",
            f"{accounted} of {lost} lost",
            "(the publishers' count minus the bag's)",
        ),
    ]


def bag_benchmarks() -> list[Row]:
    return record_and_play() + many_topics(1) + many_topics(2) + info_on_a_large_bag()
