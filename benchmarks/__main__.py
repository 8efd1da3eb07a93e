"""make bench: every figure beside its baseline from the same run, printed as one table.

python -m benchmarks [GROUP ...]
    groups: launch service topic rate memory setup turtlesim (default: all)
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import signal

from benchmarks import launch, memory, service, setup_time, topic, turtlesim
from benchmarks.common import print_table, private_domain

GROUPS = {
    "launch": lambda: launch.launch_and_shutdown() + launch.escalation(),
    "service": service.round_trip,
    "topic": lambda: topic.latency() + topic.loss_and_throughput(),
    "rate": topic.rate_accuracy,
    "memory": memory.node_memory,
    "setup": setup_time.setup_times,
    "turtlesim": turtlesim.update_rate,
}


def main() -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__)
    parser.add_argument("groups", nargs="*", metavar="GROUP", help=", ".join(GROUPS))
    args = parser.parse_args()
    unknown = [name for name in args.groups if name not in GROUPS]
    if unknown:
        parser.error(f"unknown group {unknown[0]!r}; choose from {', '.join(GROUPS)}")
    # Started in the background (nohup, `make bench &`), this process and so its children
    # would inherit SIGINT *ignored*, and a shell cannot trap a signal ignored on entry: the
    # Ctrl-C the benchmarks send would do nothing. Take the default back for the children.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    domain = private_domain()
    print(
        f"# ros-tutorials benchmarks, {datetime.date.today()}, {platform.machine()}, "
        f"{os.cpu_count()} cores, Python {platform.python_version()}, ROS_DOMAIN_ID={domain}"
    )
    rows = []
    for name in args.groups or GROUPS:
        print(f"# running {name} ...", flush=True)
        rows += GROUPS[name]()
    print()
    print_table(rows)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
