"""The project's packages are found as ROS 2 finds its own: regular packages in a folder on
sys.path (the editable install is a .pth naming the checkout), so a learner's build folder on
PYTHONPATH with a ``launch/`` folder of launch files (a namespace package to Python) does not
shadow ``launch``, as it did when an import finder asked after sys.path found them."""

from __future__ import annotations

import subprocess
import sys
import sysconfig
from pathlib import Path

from helpers import TIMEOUT

ROOT = Path(__file__).resolve().parent.parent


def test_the_editable_install_is_a_path_entry_of_the_checkout():
    site = Path(sysconfig.get_paths()["purelib"])
    entries = [
        line.strip()
        for pth in site.glob("__editable__*.pth")
        for line in pth.read_text().splitlines()
        if line.strip()
    ]
    assert str(ROOT) in entries, entries
    assert not list(site.glob("__editable__*finder.py")), "an import finder is installed"
    done = subprocess.run(
        [sys.executable, "-c", "import sys; print([type(f).__name__ for f in sys.meta_path])"],
        capture_output=True, text=True, timeout=TIMEOUT, cwd="/",
    )  # fmt: skip
    assert "Editable" not in done.stdout, done.stdout


def test_a_build_folders_launch_folder_does_not_shadow_launch(tmp_path):
    # After `colcon build --symlink-install`, build/PKG holds the package's launch/ folder
    # (launch files, no __init__.py) and is on PYTHONPATH.
    build = tmp_path / "build" / "urdf_tutorial_r2d2"
    (build / "launch").mkdir(parents=True)
    (build / "launch" / "demo_launch.py").write_text("")
    launch_file = tmp_path / "demo.launch.py"
    launch_file.write_text(
        "from launch import LaunchDescription\n"
        "from launch.actions import LogInfo\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([LogInfo(msg='planned')])\n"
    )
    env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": str(build), "HOME": str(tmp_path)}
    done = subprocess.run(
        [sys.executable, "-m", "launcher", str(launch_file), "--print"],
        capture_output=True, text=True, timeout=TIMEOUT, cwd=tmp_path, env=env,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert "planned" in done.stdout
    found = subprocess.run(
        [sys.executable, "-c", "import launch; print(launch.__file__)"],
        capture_output=True, text=True, timeout=TIMEOUT, cwd=tmp_path, env=env,
    )  # fmt: skip
    assert found.stdout.strip() == str(ROOT / "launch" / "__init__.py"), found.stderr
