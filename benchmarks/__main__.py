"""make bench: every figure beside its baseline from the same run, printed as one table.

python -m benchmarks [--smoke] [GROUP ...]
    groups: launch service topic rate memory setup bag graph daemon turtlesim web workspace
    tf2 rviz
    completion
    (default: all)
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import signal
import sys
import traceback
from collections.abc import Callable

from benchmarks import (
    bag,
    common,
    completion,
    daemon,
    graph,
    launch,
    memory,
    rviz,
    service,
    setup_time,
    tf2,
    tf2_follow,
    topic,
    turtlesim,
    web,
    workspace,
)
from benchmarks.common import Row, print_table, private_domain

# Each group is a list of steps; a step that fails costs only its own rows.
GROUPS: dict[str, list[Callable[[], list[Row]]]] = {
    "launch": [launch.launch_and_shutdown, launch.escalation, launch.formats, launch.print_tree],
    "service": [service.round_trip],
    "topic": [topic.latency, topic.loss_and_throughput],
    "rate": [topic.rate_accuracy],
    "memory": [memory.node_memory],
    "setup": [setup_time.setup_times],
    "bag": [bag.bag_benchmarks],
    "graph": [graph.lists, graph.picture],
    "daemon": [daemon.startup, daemon.lists],
    "turtlesim": [turtlesim.update_rate, turtlesim.many_turtles],
    "web": [web.viewer_figures, web.load],
    "rviz": [rviz.view_figures],
    "workspace": [workspace.build_times],
    "tf2": [tf2.lookup_chain, tf2.listener_cpu, tf2.callback_cost, tf2_follow.follow_loop],
    "completion": [completion.answer_times],
}


def main() -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__)
    parser.add_argument("groups", nargs="*", metavar="GROUP", help=", ".join(GROUPS))
    parser.add_argument(
        "--smoke",
        action="store_true",
        help="run every step briefly, to see that it runs (its figures mean nothing)",
    )
    args = parser.parse_args()
    unknown = [name for name in args.groups if name not in GROUPS]
    if unknown:
        parser.error(f"unknown group {unknown[0]!r}; choose from {', '.join(GROUPS)}")
    if args.smoke and not common.SMOKE:
        # The steps' counts and durations are read when their modules load: load them anew.
        env = {**os.environ, common.SMOKE_VARIABLE: "1"}
        os.execve(sys.executable, [sys.executable, "-m", "benchmarks", *sys.argv[1:]], env)
    # Started in the background (nohup, `make bench &`), this process and so its children
    # would inherit SIGINT *ignored*, and a shell cannot trap a signal ignored on entry: the
    # Ctrl-C the benchmarks send would do nothing. Take the default back for the children.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    # Programs run as a user runs them: from bytecode Python wrote at their first start. Where
    # the environment says PYTHONDONTWRITEBYTECODE (some shells and containers do), every
    # start compiled the launcher and the launch model anew, which the shell script never does.
    os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
    domain = private_domain()
    print(
        f"# ros-tutorials benchmarks{' (smoke run)' if common.SMOKE else ''}, "
        f"{datetime.date.today()}, {platform.machine()}, "
        f"{os.cpu_count()} cores, Python {platform.python_version()}, ROS_DOMAIN_ID={domain}"
    )
    rows: list[Row] = []
    failed = []
    for name in args.groups or GROUPS:
        load = ", ".join(f"{value:.1f}" for value in os.getloadavg())
        print(f"# running {name} ... (load average {load})", flush=True)
        for step in GROUPS[name]:
            # One step failing (an error, a timeout) must not lose the other figures.
            try:
                rows += step()
            except Exception as error:
                traceback.print_exc()
                reason = " ".join(str(error).split())[:120] or type(error).__name__
                what = f"{name}: {step.__name__} FAILED"
                rows.append(Row(what, reason, target="runs", met=False))
                failed.append(f"{name}.{step.__name__}")
    print()
    print_table(rows)
    if failed:
        print(f"\n# {len(failed)} step(s) failed: {', '.join(failed)} (tracebacks above)")
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
