"""The launcher's guardian (launcher/guardian.py): no process outlives the launcher.

The hard case: a node starts a grandchild that calls setsid (its own session and process
group) and stays alive itself, so the grandchild is in no group the launcher knows, and is
adopted by no one while its parent lives. Whatever ends the launcher, that grandchild must go.
Every process of a launch is found by a marker unique to the test in its command line, never
by timing; each test kills what it finds left, so a failure leaves nothing behind.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import time
import uuid
from pathlib import Path

import pytest
from helpers import TIMEOUT

SPAWNER = """
import signal, subprocess, sys, time
signal.signal(signal.SIGINT, lambda *_: sys.exit(0))  # a node that ends cleanly on Ctrl-C
grandchild = subprocess.Popen(
    [sys.executable, "-c", "import time; time.sleep(600)", sys.argv[1]], start_new_session=True
)
print("grandchild", grandchild.pid, flush=True)
time.sleep(600)  # the parent stays alive
"""


def _stat(pid: int) -> list[str] | None:
    """The fields of /proc/PID/stat after the command name: state, ppid, pgrp, session, ..."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return None


def marked(marker: str) -> dict[int, str]:
    """Live processes whose command line holds marker, and their state."""
    found = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            cmdline = Path(f"/proc/{entry}/cmdline").read_bytes()
        except OSError:
            continue
        stat = _stat(int(entry))
        if marker.encode() in cmdline and stat and stat[0] not in "ZX":
            found[int(entry)] = stat[0]
    return found


def assert_none_left(marker: str, timeout: float = TIMEOUT) -> None:
    deadline = time.monotonic() + timeout
    while left := marked(marker):
        if time.monotonic() > deadline:
            pytest.fail(f"{timeout:.0f} s later these processes of the launch remain: {left}")
        time.sleep(0.1)


@pytest.fixture
def launch(node_process, tmp_path):
    """Start the launch; yields (launcher, marker, pids) once the grandchild runs."""
    marker = f"guardian-test-{uuid.uuid4().hex}"
    spawner = tmp_path / f"{marker}-spawner.py"
    spawner.write_text(SPAWNER)
    path = tmp_path / f"{marker}.launch.xml"
    path.write_text(
        f'<launch><executable cmd="{sys.executable} {spawner} {marker}" name="spawner" '
        # A long sigterm_timeout: SIGTERM after SIGINT comes only from a second SIGINT (hurry).
        'output="screen" sigterm_timeout="120"/></launch>\n'
    )
    launcher = node_process("-m", "launcher", str(path))
    try:
        lines = launcher.wait_for_output(
            lambda lines: (
                any(line.startswith("[spawner] grandchild ") for line in lines)
                and any("started spawner (pid" in line for line in lines)
            ),
            what="the spawner and its grandchild",
        )
        grandchild = int(next(line for line in lines if "] grandchild " in line).split()[-1])
        node = int(next(line for line in lines if "started spawner (pid" in line).split()[-1][:-1])
        node_stat, grandchild_stat = _stat(node), _stat(grandchild)
        assert node_stat and grandchild_stat, "the node or its grandchild is already gone"
        assert int(grandchild_stat[1]) == node, "the grandchild's parent is the node, alive"
        assert grandchild_stat[3] != node_stat[3], "the grandchild has a session of its own"
        inner = int(node_stat[1])  # the launcher: the node's parent
        # The grandchild's command line can read empty for a moment after the spawner learnt
        # its pid: Linux lets Popen return (close-on-exec) before exec has set up argv.
        everyone = {launcher.process.pid, inner, node, grandchild}
        deadline = time.monotonic() + TIMEOUT
        while not everyone <= set(found := marked(marker)):
            assert time.monotonic() < deadline, (
                f"not all of {everyone} found by the marker: {found}; "
                f"the grandchild: {_stat(grandchild)}"
            )
            time.sleep(0.05)
        yield launcher, marker, {"guardian": launcher.process.pid, "launcher": inner}
    finally:  # each test checks that nothing is left; after a failure, leave nothing either
        for pid in marked(marker):
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, signal.SIGKILL)


def test_sigkill_of_the_pid_the_user_started_leaves_nothing(launch):
    launcher, marker, pids = launch
    os.kill(pids["guardian"], signal.SIGKILL)
    assert launcher.wait() == -signal.SIGKILL
    assert_none_left(marker)


def test_sigkill_of_the_launcher_inside_leaves_nothing(launch):
    launcher, marker, pids = launch
    guarded = pids["launcher"] != pids["guardian"]
    os.kill(pids["launcher"], signal.SIGKILL)
    assert launcher.wait() == -signal.SIGKILL  # the guardian ends as the launcher did
    assert_none_left(marker)
    assert guarded, "the launcher runs under a guardian"


def test_sigterm_stops_everything_in_order(launch):
    launcher, marker, _ = launch
    launcher.process.send_signal(signal.SIGTERM)
    assert launcher.wait() == 143
    assert_none_left(marker)
    assert "[launcher] all 1 process(es) stopped" in launcher.output
    assert "left their group" in launcher.output
    assert "Traceback" not in launcher.output


def test_ctrl_c_in_a_terminal_reaches_the_launcher_once(launch):
    """A terminal sends SIGINT to its foreground process group: the guardian's. The launcher
    has a group of its own and gets the one SIGINT the guardian passes on, so it stops the
    children gently (a second SIGINT would hurry them on to SIGTERM)."""
    launcher, marker, pids = launch
    assert pids["launcher"] != pids["guardian"], "the launcher runs under a guardian"
    assert os.getpgid(pids["launcher"]) != os.getpgid(pids["guardian"])
    os.killpg(pids["guardian"], signal.SIGINT)
    assert launcher.wait() == 130
    assert_none_left(marker)
    output = launcher.output
    assert "[launcher] all 1 process(es) stopped" in output
    assert "sending SIGTERM" not in output and "sending SIGKILL" not in output
    assert "Traceback" not in output and "KeyboardInterrupt" not in output


def test_exit_code_and_output_pass_through_the_guardian(node_process, tmp_path):
    path = tmp_path / "fail.launch.xml"
    path.write_text(
        f"<launch><executable cmd=\"{sys.executable} -c 'print(7); raise SystemExit(3)'\" "
        'name="fail" output="screen"/></launch>\n'
    )
    launcher = node_process("-m", "launcher", str(path))
    assert launcher.wait() == 1
    assert "[fail] 7" in launcher.lines
    assert "[launcher] fail died with exit code 3" in launcher.lines
