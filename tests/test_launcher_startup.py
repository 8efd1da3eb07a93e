"""What the launcher loads before its first process (issue 39: union.launch within 1.10 x a
shell script; docs/dev/performance.md). No timings here: which modules a plan needs.

Each check plans a file with ``--print`` in a fresh interpreter and reports which of the
modules the launcher imports only when a file needs them it then holds.
"""

from __future__ import annotations

import importlib.metadata
import json
import subprocess
import sys
from pathlib import Path

from ros_tutorials_common import packages

ON_DEMAND = ("yaml", "importlib.metadata", "launch_xml")
PROBE = """
import contextlib, io, json, sys
from launcher.__main__ import main
with contextlib.redirect_stdout(io.StringIO()):
    status = main(sys.argv[1:] + ["--print"])
print(json.dumps([status, [m for m in {modules!r} if m in sys.modules]]))
"""


def loaded_by_planning(*words: str) -> tuple[int, list[str]]:
    done = subprocess.run(
        [sys.executable, "-c", PROBE.format(modules=ON_DEMAND), *words],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    status, loaded = json.loads(done.stdout.splitlines()[-1])
    return status, loaded


def test_planning_union_launch_loads_no_yaml_metadata_or_xml_front_end():
    assert loaded_by_planning("union.launch") == (0, [])


def test_a_file_that_needs_them_loads_them(tmp_path: Path):
    # The probe sees these modules when a plan does need them: the check above can fail.
    launch = tmp_path / "two.launch.yaml"
    launch.write_text(
        "launch:\n"
        "- set_env: {name: GREETING, value: hello}\n"
        "- node: {pkg: ros_tutorials_topic, exec: topic_publisher}\n"
    )
    status, loaded = loaded_by_planning(str(launch))
    assert status == 0 and {"yaml", "launch_xml"} <= set(loaded)


def test_console_scripts_are_what_the_distribution_declares():
    # packages.py reads the project's entry_points.txt itself, not through importlib.metadata
    # (its import was a third of the launcher's start): the same table, name for name.
    declared = importlib.metadata.distribution(packages.DISTRIBUTION).entry_points
    expected = sorted((s.name, s.value) for s in declared if s.group == "console_scripts")
    assert len(expected) > 20
    assert sorted(packages._project_scripts()) == expected
