"""Graph figures (issue 12): how long `ros2 node list` / `topic list` take to give the
complete answer with union.launch and 20 more nodes running, beside the time discovery
itself needs (a bare rclpy node that knows what to expect and waits until it sees it all);
and how long the graph picture of 50 nodes and 100 topics takes."""

from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from pathlib import Path

from benchmarks.common import Row, fmt_ms, p50, p99, python, smoke, start, stop

EXTRA_NODES = smoke(20, 2)
UNION = ["/ns1/topic_publisher", "/ns1/topic_subscriber", "/ns2/topic_publisher"]
UNION.append("/ns2/topic_subscriber")
EXPECTED_NODES = sorted(UNION + [f"/extra_{n}" for n in range(EXTRA_NODES)])
EXPECTED_TOPICS = sorted(
    ["/ns1/ros_tutorial_msg", "/ns2/ros_tutorial_msg", "/parameter_events", "/rosout"]
    + [f"/chatter_{n}" for n in range(EXTRA_NODES)]
)
BIN = Path(sys.executable).parent

# The baseline: a bare rclpy node that polls the graph until it holds all it expects.
BARE = """
import sys, rclpy
from rclpy.node import Node
from ros_tutorials_common.dds import apply_dds_defaults
nodes, topics = set(sys.argv[1].split(',')), set(sys.argv[2].split(','))
apply_dds_defaults(); rclpy.init(); node = Node('_bare')
def complete():
    seen = {ns.rstrip('/') + '/' + n for n, ns in node.get_node_names_and_namespaces()}
    return nodes <= seen and topics <= {t for t, _ in node.get_topic_names_and_types()}
while not complete():
    rclpy.spin_once(node, timeout_sec=0.01)
"""


def _running() -> list[subprocess.Popen]:
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    procs = [start(python("-m", "launcher", "union.launch"), **quiet)]
    for n in range(EXTRA_NODES):
        args = ["--ros-args", "-r", f"__node:=extra_{n}", "-r", f"chatter:=chatter_{n}"]
        procs.append(start(python("-m", "ros_tutorials_topic.talker", *args), **quiet))
    return procs


def _timed(args: list[str]) -> tuple[float, str]:
    began = time.monotonic()
    out = subprocess.run(args, capture_output=True, text=True, timeout=60)
    return time.monotonic() - began, out.stdout


def lists(runs: int = smoke(10, 1)) -> list[Row]:
    procs = _running()
    try:
        bare = python("-c", BARE, ",".join(EXPECTED_NODES), ",".join(EXPECTED_TOPICS))
        _timed(bare)  # everything is up once a bare node sees it all
        samples: dict[str, list[float]] = {"node": [], "topic": [], "bare": []}
        complete = {"node": 0, "topic": 0}
        for _ in range(runs):  # interleaved, so machine load hits all alike
            for verb, expected in (("node", EXPECTED_NODES), ("topic", EXPECTED_TOPICS)):
                seconds, out = _timed([str(BIN / "ros2"), verb, "list", "--no-daemon"])
                samples[verb].append(seconds)
                complete[verb] += out.split() == expected
                if out.split() != expected:  # say what differed: the table only counts
                    listed = set(out.split())
                    print(
                        f"`ros2 {verb} list` missed {sorted(set(expected) - listed)}, "
                        f"listed more: {sorted(listed - set(expected))}",
                        file=sys.stderr,
                    )
            samples["bare"].append(_timed(bare)[0])
        dot = str(Path(tempfile.gettempdir()) / "benchmark_graph.dot")
        graph_seconds = [_timed([str(BIN / "rqt_graph"), "-o", dot])[0] for _ in range(3)]
    finally:
        for proc in procs:
            stop(proc)
    base = samples["bare"]
    rows = []
    for verb in ("node", "topic"):
        s = samples[verb]
        rows.append(
            Row(
                f"`ros2 {verb} list`, union.launch + {EXTRA_NODES} nodes, start to exit, "
                f"p50/p99 of {runs} (complete: {complete[verb]}/{runs})",
                f"{fmt_ms(p50(s))} / {fmt_ms(p99(s))}",
                f"{fmt_ms(p50(base))} / {fmt_ms(p99(base))} (bare rclpy node seeing all)",
                p50(s) / p50(base),
                "complete every run",
                complete[verb] == runs,
            )
        )
    rows.append(
        Row(
            f"`rqt_graph -o graph.dot`, the same {len(EXPECTED_NODES)} nodes, median of 3",
            fmt_ms(p50(graph_seconds)),
        )
    )
    return rows


def picture(runs: int = smoke(5, 1)) -> list[Row]:
    """Layout and drawing alone (no ROS), for a made-up graph of 50 nodes and 100 topics."""
    from ros_tutorials_common.drawing.model import example_model
    from ros_tutorials_common.drawing.render import write

    model = example_model(50, 100)
    rows = []
    with tempfile.TemporaryDirectory() as out:
        for suffix in ("svg", "png"):
            seconds = []
            for _ in range(runs):
                began = time.monotonic()
                write(model, Path(out) / f"g.{suffix}")
                seconds.append(time.monotonic() - began)
            rows.append(
                Row(
                    f"graph picture, 50 nodes + 100 topics (made up), layout + "
                    f"{suffix.upper()}, median of {runs}",
                    fmt_ms(p50(seconds)),
                )
            )
    return rows
