"""What every benchmark shares: a private ROS domain, child processes, statistics, the table."""

from __future__ import annotations

import json
import os
import signal
import statistics
import subprocess
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from ros_tutorials_common.dds import apply_dds_defaults, claim_private_domain_id

_domain_lock = None

# Set (to anything but empty), every step runs briefly: the smoke run `make test` does
# (tests/test_benchmarks.py), that only shows that each step still runs; its figures mean
# nothing. `python -m benchmarks --smoke` sets it.
SMOKE_VARIABLE = "ROS_TUTORIALS_BENCH_SMOKE"
SMOKE = bool(os.environ.get(SMOKE_VARIABLE))


def smoke(full, brief):
    """FULL in a measuring run, BRIEF in a smoke run (a count, a duration)."""
    return brief if SMOKE else full


def private_domain() -> int:
    """Claim a ROS_DOMAIN_ID for this benchmark run and set it, with the DDS defaults."""
    global _domain_lock
    if _domain_lock is None:
        domain_id, _domain_lock = claim_private_domain_id()
        os.environ["ROS_DOMAIN_ID"] = str(domain_id)
        apply_dds_defaults()
    return int(os.environ["ROS_DOMAIN_ID"])


def p50(samples: Sequence[float]) -> float:
    return statistics.median(samples)


def p99(samples: Sequence[float]) -> float:
    if len(samples) < 2:
        return samples[0]
    return statistics.quantiles(samples, n=100, method="inclusive")[98]


@dataclass
class Row:
    """One line of the table: a figure, its baseline from the same run, the target."""

    what: str
    value: str
    baseline: str = ""
    ratio: float | None = None
    target: str = ""
    met: bool | None = None


def fmt_ms(seconds: float) -> str:
    return f"{seconds * 1e3:.2f} ms" if seconds < 1 else f"{seconds:.2f} s"


def fmt_us(seconds: float) -> str:
    return f"{seconds * 1e6:.0f} us"


def print_table(rows: Sequence[Row]) -> None:
    headers = ("what", "this project", "baseline", "ratio", "target", "met")
    cells = [
        (
            r.what,
            r.value,
            r.baseline,
            "" if r.ratio is None else f"{r.ratio:.2f}",
            r.target,
            "" if r.met is None else ("yes" if r.met else "NO"),
        )
        for r in rows
    ]
    widths = [max(len(h), *(len(c[i]) for c in cells)) for i, h in enumerate(headers)]
    line = " | ".join(h.ljust(w) for h, w in zip(headers, widths, strict=False))
    print(f"| {line} |")
    print("|" + "|".join("-" * (w + 2) for w in widths) + "|")
    for c in cells:
        print("| " + " | ".join(v.ljust(w) for v, w in zip(c, widths, strict=False)) + " |")


def start(args: Sequence[str], **kwargs) -> subprocess.Popen:
    """Start a child in its own process group with output captured (text, line by line)."""
    env = {**os.environ, "PYTHONUNBUFFERED": "1", **kwargs.pop("env", {})}
    return subprocess.Popen(
        list(args),
        stdout=kwargs.pop("stdout", subprocess.PIPE),
        stderr=kwargs.pop("stderr", subprocess.STDOUT),
        text=True,
        env=env,
        start_new_session=True,
        **kwargs,
    )


def python(*args: str) -> list[str]:
    return [sys.executable, *args]


def run_worker(module: str, *args: str) -> dict:
    """Run ``python -m module args`` to the end; its last stdout line is its JSON result."""
    out = subprocess.run(
        python("-m", module, *args), capture_output=True, text=True, timeout=300, check=True
    )
    return json.loads(out.stdout.strip().splitlines()[-1])


def stop(proc: subprocess.Popen, timeout: float = 10.0) -> None:
    """Ctrl-C the child's process group; kill it if it does not go."""
    if proc.poll() is None:
        os.killpg(proc.pid, signal.SIGINT)
        try:
            proc.wait(timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()


def wait_for_lines(proc: subprocess.Popen, done: Callable[[str], bool], timeout: float) -> bool:
    """Read the child's output until done(line_so_far_seen) is true; False on timeout/exit."""
    assert proc.stdout is not None
    deadline = time.monotonic() + timeout
    os.set_blocking(proc.stdout.fileno(), True)
    for line in proc.stdout:
        if done(line):
            return True
        if time.monotonic() > deadline:
            return False
    return False


def peak_rss_mib(pid: int) -> float:
    """Peak resident set size (VmHWM) of a live process, in MiB."""
    with open(f"/proc/{pid}/status") as status:
        for line in status:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024
    raise RuntimeError(f"no VmHWM for pid {pid}")
