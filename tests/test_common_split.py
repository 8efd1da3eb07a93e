"""ros_tutorials_common in two parts: its top-level modules never import rclpy (the launcher
uses them, and the launcher stays light), ``ros_tutorials_common.ros`` does.

Each check runs in a fresh interpreter, which imports the modules and reports which rclpy
modules (and rcl extension modules) it then holds.
"""

from __future__ import annotations

import json
import pkgutil
import subprocess
import sys
from pathlib import Path

import ros_tutorials_common

PLAIN = sorted(
    f"ros_tutorials_common.{info.name}"
    for info in pkgutil.iter_modules(ros_tutorials_common.__path__)
    if info.name != "ros"
)
LAUNCHER = [
    "launcher.__main__",
    "launch_foundation.declarations",
    "launch_foundation.parse",
    "launch_foundation.substitutions",
    "launcher.plan",
    "launcher.loading",
    "launcher.ros1",
    "launcher.ros1_substitutions",
    "launcher.ros2_markup",
    "launcher.service",
    "launcher.supervise",
]
PROBE = """
import importlib, json, sys
for name in sys.argv[1:]:
    importlib.import_module(name)
print(json.dumps(sorted(m for m in sys.modules if m.split(".")[0] in ("rclpy", "rpyutils"))))
"""


def rclpy_modules_after_importing(*modules: str) -> list[str]:
    done = subprocess.run(
        [sys.executable, "-c", PROBE, *modules], capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_the_plain_part_and_the_launcher_import_no_rclpy():
    assert {"ros_tutorials_common.bounded", "ros_tutorials_common.dds"} <= set(PLAIN)
    assert rclpy_modules_after_importing("ros_tutorials_common", *PLAIN, *LAUNCHER) == []


def test_the_ros_part_is_where_rclpy_is():
    # The probe does see rclpy when it is imported: the check above can fail.
    assert "rclpy" in rclpy_modules_after_importing("ros_tutorials_common.ros")


def test_one_place_imports_a_private_rclpy_module():
    root = Path(ros_tutorials_common.__file__).resolve().parents[1]
    sources = [
        path
        for folder in root.iterdir()
        if folder.is_dir() and folder.name not in {".venv", "build", "tests"}
        for path in folder.rglob("*.py")
    ]
    assert len(sources) > 50
    private = sorted(
        str(path.relative_to(root)) for path in sources if "rclpy.impl" in path.read_text()
    )
    assert private == ["ros_tutorials_common/ros/node_main.py"]
