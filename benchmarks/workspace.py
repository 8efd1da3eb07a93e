"""The learner's own packages: `colcon build` of an ament_python package (`ros2 pkg create
--node-name my_node my_package`) and of the Custom-ROS2-Interfaces page's tutorial_interfaces
(two msg, one srv), seconds and CPU, beside the set-up's own build of interfaces/
(tools/build_interfaces.py, colcon, into a temporary prefix).
"""

from __future__ import annotations

import resource
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from benchmarks.common import SMOKE, Row

ROOT = Path(__file__).resolve().parent.parent
ACTIVATE = Path(sys.prefix) / "bin" / "activate"
DATA = ROOT / "tests" / "data" / "workspace"


def _timed(script: str, cwd: Path) -> tuple[float, float]:
    """Wall and CPU seconds (the children's user + system) of a bash script run to its end."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    activate = f". {shlex.quote(str(ACTIVATE))}\n"
    subprocess.run(["bash", "-c", activate + script], cwd=cwd, check=True, capture_output=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def _interfaces_package(src: Path) -> None:
    subprocess.run(
        ["bash", "-c", f". {shlex.quote(str(ACTIVATE))}\nros2 pkg create tutorial_interfaces"],
        cwd=src,
        check=True,
        capture_output=True,
    )
    package = src / "tutorial_interfaces"
    files = {
        "msg/Num.msg": "int64 num\n",
        "msg/Sphere.msg": "geometry_msgs/Point center\nfloat64 radius\n",
        "srv/AddThreeInts.srv": "int64 a\nint64 b\nint64 c\n---\nint64 sum\n",
    }
    for name, text in files.items():
        (package / name).parent.mkdir(exist_ok=True)
        (package / name).write_text(text)
    for file, anchor, data in (
        ("CMakeLists.txt", "find_package(ament_cmake REQUIRED)", "tutorial_interfaces_CMakeLists"),
        ("package.xml", "<license>", "tutorial_interfaces_package"),
    ):
        path = package / file
        text = path.read_text()
        at = text.index("\n", text.index(anchor)) + 1
        added = next(DATA.glob(f"{data}.*")).read_text()
        path.write_text(text[:at] + added + text[at:])


def build_times() -> list[Row]:
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        workspace = Path(tmp) / "ros2_ws"
        src = workspace / "src"
        src.mkdir(parents=True)
        create = "ros2 pkg create --build-type ament_python --node-name my_node my_package"
        subprocess.run(
            ["bash", "-c", f". {ACTIVATE}\n{create}"], cwd=src, check=True, capture_output=True
        )
        wall, cpu = _timed("colcon build --packages-select my_package", workspace)
        rows.append(
            Row("colcon build: ament_python my_package", f"{wall:.1f} s", f"CPU {cpu:.1f} s")
        )
        if SMOKE:  # the CMake builds take minutes each
            return rows
        _interfaces_package(src)
        wall, cpu = _timed("colcon build --packages-select tutorial_interfaces", workspace)
        rows.append(
            Row(
                "colcon build: tutorial_interfaces (2 msg, 1 srv)",
                f"{wall:.1f} s",
                f"CPU {cpu:.1f} s",
            )
        )
        build = Path(tmp) / "build"
        prefix = Path(tmp) / "prefix"
        script = (
            f"python {ROOT / 'tools' / 'build_interfaces.py'} --prefix {prefix} --build {build}"
        )
        wall, cpu = _timed(script, ROOT)
        count = len(list((ROOT / "interfaces").glob("*/package.xml")))
        rows.append(
            Row(
                f"set-up's interfaces/ build ({count} packages)",
                f"{wall:.1f} s",
                f"CPU {cpu:.1f} s",
            )
        )
    return rows
