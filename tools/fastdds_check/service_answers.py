"""How many service answers are lost while discovery finishes, with UDP packets dropped.

It checks a claim of ros_tutorials_common/config/fastdds.xml and docs/dev/limits.md: a
server that got a request before it found the client's reader drops the answer after
100 ms (Fast DDS's default max_blocking_time, ros2/rmw_fastrtps#842), and the project's
"service" writer profile (5 s) keeps it. Each round starts the workshop's
add_two_ints_client, then its server, as two people starting them in two terminals, in a
network namespace of its own whose loopback drops a share of its UDP packets, and counts
the clients that got no answer within their 30 s.

    sudo .venv/bin/python tools/fastdds_check/service_answers.py [--rounds 40] [--drop 0.15]
        [--without-service-writer]

Needs root, ip(8) and iptables(8). Nothing leaves the namespace, which is removed at the end.
Exit status: 0 if no answer was lost, 3 if some were, 1 if it cannot run.
"""

from __future__ import annotations

import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from ros_tutorials_common.dds import DDS_DEFAULTS, apply_dds_defaults  # noqa: E402

CLIENT = "ros_tutorials_service.workshop_add_two_ints_client"
SERVER = "ros_tutorials_service.workshop_add_two_ints_server"


def namespace(name: str, drop: float) -> str | None:
    """Set up network namespace NAME: loopback up, dropping DROP of the UDP packets it
    receives. What failed, as one line; None if all went well."""
    inside = ["ip", "netns", "exec", name]
    rule = ["-p", "udp", "-m", "statistic", "--mode", "random", "--probability", str(drop)]
    for step in (
        ["ip", "netns", "add", name],
        [*inside, "ip", "link", "set", "lo", "up"],
        [*inside, "iptables", "-A", "INPUT", *rule, "-j", "DROP"],
    ):
        done = subprocess.run(step, capture_output=True, text=True)
        if done.returncode != 0:
            return f"{' '.join(step)}: {done.stderr.strip() or f'exit {done.returncode}'}"
    return None


def one_round(inside: list[str], env: dict[str, str]) -> tuple[bool, str]:
    """Client first, then server; whether the client printed the sum, and the server's words."""
    quiet = {"stdout": subprocess.PIPE, "stderr": subprocess.STDOUT, "text": True, "env": env}
    python = [*inside, sys.executable, "-m"]
    client = subprocess.Popen([*python, CLIENT, "1", "2"], cwd=ROOT, **quiet)
    server = subprocess.Popen([*python, SERVER], cwd=ROOT, **quiet)
    try:
        answered = "1 + 2 = 3" in client.communicate(timeout=60)[0]
    except subprocess.TimeoutExpired:
        client.kill()
        answered = False
    server.send_signal(signal.SIGINT)
    try:
        said = server.communicate(timeout=30)[0]
    except subprocess.TimeoutExpired:
        server.kill()
        said = server.communicate()[0]
    return answered, said


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="service_answers.py", description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=40)
    parser.add_argument("--drop", type=float, default=0.15, help="share of UDP packets dropped")
    parser.add_argument("--domain-id", type=int, default=150)
    parser.add_argument(
        "--without-service-writer",
        action="store_true",
        help="the project's profile without its \"service\" writer: Fast DDS's 100 ms",
    )
    options = parser.parse_args(argv)
    if not 0 <= options.drop < 1 or options.rounds < 1 or not 0 <= options.domain_id <= 232:
        parser.error("--drop is a share from 0 to below 1, --rounds at least 1, "
                     "--domain-id from 0 to 232")  # fmt: skip
    missing = [tool for tool in ("ip", "iptables") if shutil.which(tool) is None]
    if os.geteuid() != 0 or missing:
        lacking = ([] if os.geteuid() == 0 else ["root"]) + missing
        print(f"service_answers.py needs root, ip and iptables; lacking: {', '.join(lacking)}",
              file=sys.stderr)  # fmt: skip
        return 1

    env = {**os.environ, "ROS_DOMAIN_ID": str(options.domain_id)}
    apply_dds_defaults(env)
    with tempfile.TemporaryDirectory() as scratch:
        if options.without_service_writer:
            profile = Path(DDS_DEFAULTS["FASTRTPS_DEFAULT_PROFILES_FILE"]).read_text()
            without = Path(scratch) / "without_service_writer.xml"
            without.write_text(profile[: profile.index("  <data_writer")] + "</profiles>\n")
            env["FASTRTPS_DEFAULT_PROFILES_FILE"] = str(without)
        name = f"rt_service_answers_{os.getpid()}"
        lost = dropped = 0
        try:
            problem = namespace(name, options.drop)
            if problem:
                print(f"cannot set up the network namespace: {problem}", file=sys.stderr)
                return 1
            for number in range(1, options.rounds + 1):
                answered, said = one_round(["ip", "netns", "exec", name], env)
                lost += not answered
                dropped += "client will not receive response" in said
                print(f"round {number}: {'answered' if answered else 'NO ANSWER'}", flush=True)
        finally:
            subprocess.run(["ip", "netns", "delete", name], capture_output=True, check=False)
    profile = env["FASTRTPS_DEFAULT_PROFILES_FILE"]
    print(f"{lost} of {options.rounds} answers lost ({dropped} dropped by the server, "
          f"'client will not receive response'); {options.drop:.0%} of UDP packets dropped; "
          f"profile {profile}")  # fmt: skip
    return 3 if lost else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
