"""The README's first command: `make run`, stopped with Ctrl-C as the README says, ends
quietly (no `make: *** ... Error 130` that would make a newcomer think it failed)."""

from __future__ import annotations

import os
import signal
import subprocess
import threading
from pathlib import Path

from helpers import TIMEOUT

ROOT = Path(__file__).resolve().parent.parent


def test_ctrl_c_ends_make_run_quietly():
    # -o setup: the set-up is done (this suite runs in it); make must not start it again.
    make = subprocess.Popen(
        ["make", "--no-print-directory", "-o", "setup", "run"],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        start_new_session=True,  # a process group of its own, as a terminal's foreground job
    )
    lines: list[str] = []
    received = threading.Event()

    def read() -> None:
        for line in make.stdout:
            lines.append(line)
            if "recieve msg" in line:
                received.set()

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    try:
        assert received.wait(TIMEOUT), "no subscriber printed a message:\n" + "".join(lines)
        os.killpg(make.pid, signal.SIGINT)  # Ctrl-C: the terminal signals the whole group
        status = make.wait(TIMEOUT)
    finally:
        if make.poll() is None:
            os.killpg(make.pid, signal.SIGKILL)
            make.wait()
    reader.join(TIMEOUT)
    output = "".join(lines)
    # make got the SIGINT too: it ends by it, silently, as any program stopped with Ctrl-C.
    assert status in (0, -signal.SIGINT), output
    assert not [line for line in lines if line.startswith("make")], output
    assert "Traceback" not in output
