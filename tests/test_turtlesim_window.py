"""turtlesim's window, seen as a user sees it, on a virtual X display (Xvfb): a window that
covered it and closes leaves no pixels behind (it kept them until the next key press).

Needs Xvfb, xmessage and xwd (Debian: xvfb, x11-utils, x11-apps), which this project does not
install; skipped with that reason where they are missing."""

from __future__ import annotations

import os
import shutil
import struct
import subprocess
import time
from pathlib import Path

import pytest
from helpers import BIN, NodeProcess

TOOLS = ("Xvfb", "xmessage", "xwd")
BACKGROUND_BGR = (255, 86, 69)  # turtlesim's background (69, 86, 255), as xwd stores it


def _pixels(xwd: bytes) -> tuple[int, int, callable]:
    header = struct.unpack(">25I", xwd[:100])
    size, width, height, depth, per_line, colours = (
        header[0], header[4], header[5], header[11], header[12], header[19],
    )  # fmt: skip
    start, step = size + colours * 12, depth // 8

    def at(x: int, y: int) -> tuple[int, ...]:
        offset = start + y * per_line + x * step
        return tuple(xwd[offset : offset + 3])

    return width, height, at


@pytest.mark.skipif(
    any(shutil.which(tool) is None for tool in TOOLS),
    reason="needs a browser or display: Xvfb, xmessage and xwd (apt: xvfb x11-utils x11-apps)",
)
def test_a_window_that_covered_turtlesim_leaves_nothing_behind(tmp_path: Path, ros_domain):
    display = f":{100 + ros_domain}"
    server = subprocess.Popen(["Xvfb", display, "-screen", "0", "800x600x24"])
    env = {"DISPLAY": display, "WAYLAND_DISPLAY": "", "SDL_VIDEODRIVER": ""}
    sim = None
    try:
        sim = NodeProcess(str(BIN / "turtlesim_node"), env=env, cold=True)
        sim.wait_for_text("Spawning turtle [turtle1]")
        shot = tmp_path / "shot.xwd"

        def screen() -> tuple[int, int, callable]:
            with open(shot, "wb") as out:
                subprocess.run(["xwd", "-root", "-silent"], stdout=out, check=True, env=env)
            return _pixels(shot.read_bytes())

        deadline = time.monotonic() + 30
        while True:  # the window is drawn: find where
            width, height, at = screen()
            blue = [
                (x, y)
                for y in range(0, height, 5)
                for x in range(0, width, 5)
                if at(x, y) == BACKGROUND_BGR
            ]
            if blue or time.monotonic() > deadline:
                break
            time.sleep(0.2)
        assert blue, "turtlesim's window never appeared"
        left, top = min(x for x, _ in blue), min(y for _, y in blue)
        right, bottom = max(x for x, _ in blue), max(y for _, y in blue)
        cover = subprocess.Popen(
            ["xmessage", "-geometry", f"300x300+{left + 10}+{top + 10}", "cover " * 20],
            env={**os.environ, **env},
        )
        time.sleep(1.5)  # shown for a while (nothing depends on how long)
        cover.kill()
        cover.wait()

        def leftovers() -> int:
            _, _, at = screen()
            return sum(
                at(x, y) != BACKGROUND_BGR
                for y in range(top + 5, bottom, 5)
                for x in range(left + 5, right, 5)
            )

        deadline = time.monotonic() + 30
        while (left_over := leftovers()) > 150 and time.monotonic() < deadline:
            time.sleep(0.2)  # the turtle itself is under 100 of these samples
        assert left_over <= 150, f"{left_over} samples still show the closed window"
    finally:
        if sim is not None:
            sim.interrupt()
            sim.wait()
        server.terminate()
        server.wait()
