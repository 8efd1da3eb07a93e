"""`roscore`: says why ROS 2 needs none, and waits until Ctrl-C.

Every seed starts with `roscore` in a terminal of its own. ROS 2 has no master: this keeps
that terminal busy, as the seeds' layout expects, and explains what takes its place.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
from collections.abc import Sequence

from ros_tutorials_common import completion
from ros_tutorials_common.dds import apply_dds_defaults
from ros_tutorials_common.shutdown import program_main, terminate_as_ctrl_c


def explanation(env: dict[str, str]) -> str:
    """What a learner needs instead of a master, with the settings of this environment."""
    user_set_range = "ROS_AUTOMATIC_DISCOVERY_RANGE" in env
    env = dict(apply_dds_defaults(dict(env)))  # what every node of this project will use
    domain = env.get("ROS_DOMAIN_ID") or "0 (not set)"
    discovery_range = env["ROS_AUTOMATIC_DISCOVERY_RANGE"]
    reach = {
        "LOCALHOST": "only nodes on this machine",
        "SUBNET": "nodes on this machine and on its local network",
        "SYSTEM_DEFAULT": "as far as the DDS implementation's default reaches",
        "OFF": "no other process at all",
    }.get(discovery_range, "see the ROS 2 documentation for this value")
    default = "" if user_set_range else ", this project's default"
    return "\n".join(
        [
            "ROS 2 has no master: there is nothing to start here, and nothing to wait for.",
            "Nodes find each other by DDS discovery: each one announces itself and listens",
            "for the others, so start them in any order, in other terminals (rosrun, roslaunch).",
            f"  ROS_DOMAIN_ID={domain}: only nodes with the same domain id see each other.",
            f"  ROS_AUTOMATIC_DISCOVERY_RANGE={discovery_range}: {reach}{default}.",
            "Each node keeps its own parameters (rosparam works on them) and publishes its",
            "log on /rosout itself. This terminal only waits; Ctrl-C closes it.",
        ]
    )


def show_and_wait() -> None:
    """Print the explanation, then sleep until Ctrl-C (SIGINT) or SIGTERM: a normal end."""
    terminate_as_ctrl_c()
    try:
        print(explanation(dict(os.environ)), flush=True)
        while True:
            signal.pause()
    except KeyboardInterrupt:
        pass


@program_main
def roscore(argv: Sequence[str] | None = None) -> int:
    """The `roscore` command (console script)."""
    parser = argparse.ArgumentParser(
        prog="roscore", description="ROS 2 has no master; says what replaces it, waits for Ctrl-C."
    )
    completion.answer(parser)  # the shell asking for TAB's completions: ends here
    parser.parse_args(sys.argv[1:] if argv is None else argv)
    show_and_wait()
    return 0
