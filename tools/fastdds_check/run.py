"""Build and run set_listener_deadlock.cpp against this environment's Fast DDS wheel.

It checks a claim of docs/dev/limits.md: Fast DDS's ``DomainParticipant::set_listener(nullptr)``,
which rmw_fastrtps calls when a process's last node is destroyed, never returns if a
discovery callback was running when it was called (the PyPI wheel's deadlock). When a new
wheel fixes it, this prints the time it took and exits 0, and the docs must change.

    .venv/bin/python tools/fastdds_check/run.py [DOMAIN_ID]

Exit status: the program's (0 returned, 3 the deadlock, 2 no discovery), or 1 if it cannot be
built (no C++ compiler). Shared memory only: nothing is sent on any network.
"""

from __future__ import annotations

import os
import random
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

HERE = Path(__file__).resolve().parent
SOURCE = HERE / "set_listener_deadlock.cpp"
BUILD = HERE.parents[1] / "build" / "fastdds_check"
TIMEOUT_SECONDS = 60


def library_dirs() -> list[Path]:
    """Where the wheels put libfastrtps and the libraries it was linked with."""
    site = Path(sysconfig.get_paths()["purelib"])
    return [Path(sys.prefix) / "lib", site / "ros_fastrtps.libs"]


def build() -> Path | None:
    compiler = shutil.which("g++") or shutil.which("c++")
    if compiler is None:
        print("no C++ compiler (g++): cannot build the check", file=sys.stderr)
        return None
    BUILD.mkdir(parents=True, exist_ok=True)
    binary = BUILD / "set_listener_deadlock"
    if binary.exists() and binary.stat().st_mtime >= SOURCE.stat().st_mtime:
        return binary
    include = Path(sys.prefix) / "include"
    command = [
        compiler, "-std=c++17", "-O1", str(SOURCE), f"-I{include}", f"-I{include / 'fastcdr'}",
        f"-L{Path(sys.prefix) / 'lib'}", "-lfastrtps", "-lfastcdr", "-pthread",
        # libfastrtps's own dependencies are found at run time (LD_LIBRARY_PATH below)
        "-Wl,--allow-shlib-undefined", "-o", str(binary),
    ]  # fmt: skip
    built = subprocess.run(command, capture_output=True, text=True)
    if built.returncode != 0:
        print(f"could not build the check:\n{built.stderr.strip()}", file=sys.stderr)
        return None
    return binary


def main(argv: list[str]) -> int:
    binary = build()
    if binary is None:
        return 1
    domain = argv[0] if argv else str(random.randint(1, 101))
    env = dict(os.environ)
    paths = [str(p) for p in library_dirs()] + [env.get("LD_LIBRARY_PATH", "")]
    env["LD_LIBRARY_PATH"] = os.pathsep.join(p for p in paths if p)
    try:
        ran = subprocess.run([str(binary), domain], env=env, timeout=TIMEOUT_SECONDS)
    except subprocess.TimeoutExpired:
        print(f"the check did not end within {TIMEOUT_SECONDS} s", file=sys.stderr)
        return 1
    return ran.returncode


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
