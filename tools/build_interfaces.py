"""Generate and install interfaces/ (ros_tutorials_interfaces) into this virtual environment.

Runs the real rosidl tool chain from the ROS 2 Jazzy wheels through CMake, the way colcon
would, and installs into sys.prefix: the Python package lands in site-packages and the
type-support libraries in sys.prefix/lib, where the wheels' loader already looks.
The build tree (build/interfaces) is kept, so a changed definition rebuilds only what changed.

    .venv/bin/python tools/build_interfaces.py
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SOURCE = ROOT / "interfaces"
BUILD = ROOT / "build" / "interfaces"


def find_cmake() -> str:
    """Prefer the CMake installed into the venv (from PyPI), then the system's."""
    venv_cmake = Path(sys.prefix) / "bin" / "cmake"
    if venv_cmake.exists():
        return str(venv_cmake)
    found = shutil.which("cmake")
    if found is None:
        sys.exit("build_interfaces: CMake not found; run 'make setup' or install CMake >= 3.22")
    return found


def main() -> int:
    prefix = sys.prefix
    env = dict(os.environ)
    # ament's resource index and CMake's package search both start at the venv prefix.
    env["AMENT_PREFIX_PATH"] = prefix
    env["CMAKE_PREFIX_PATH"] = prefix
    env["PATH"] = f"{Path(prefix) / 'bin'}{os.pathsep}{env.get('PATH', '')}"
    cmake = find_cmake()
    BUILD.mkdir(parents=True, exist_ok=True)
    steps = [
        [
            cmake,
            "-S",
            str(SOURCE),
            "-B",
            str(BUILD),
            f"-DCMAKE_INSTALL_PREFIX={prefix}",
            f"-DCMAKE_PREFIX_PATH={prefix}",
            f"-DPython3_EXECUTABLE={sys.executable}",
            "-DROS_TUTORIALS_FIX_WHEEL_TARGETS=ON",
            "-DBUILD_TESTING=OFF",
        ],
        [cmake, "--build", str(BUILD), "--parallel", str(os.cpu_count() or 2)],
        [cmake, "--install", str(BUILD)],
    ]
    log_path = BUILD / "build.log"
    with log_path.open("w") as log:
        for step in steps:
            log.write(f"$ {' '.join(step)}\n")
            log.flush()
            result = subprocess.run(step, env=env, stdout=log, stderr=subprocess.STDOUT)
            if result.returncode != 0:
                print(log_path.read_text()[-4000:], file=sys.stderr)
                print(
                    f"build_interfaces: step failed: {' '.join(step[:2])}; full log in {log_path}",
                    file=sys.stderr,
                )
                return 1
    print(f"ros_tutorials_interfaces generated and installed into {prefix}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
