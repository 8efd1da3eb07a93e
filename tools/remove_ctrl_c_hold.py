"""`make setup` in a venv made by an older clone: undo what its set-up did for Ctrl-C.

It wrote a .pth file that blocked SIGINT at every start of Python, and rewrote this project's
console scripts to start through `env -S --block-signal=INT`. Both are gone (Ctrl-C is handled
by the tools themselves: ros_tutorials_common/shutdown.py); this removes the file and gives the
scripts back pip's plain "#!/path/to/python" line. Run as `python -S` (the old .pth file,
which now fails, is not read): python -S tools/remove_ctrl_c_hold.py VENV
"""

from __future__ import annotations

import glob
import os
import sys

PTH_NAME = "00_ros_tutorials_ctrl_c.pth"
HELD = "#!/usr/bin/env -S --block-signal=INT "


def remove_hold(venv: str) -> list[str]:
    """What it undid in the venv at VENV, one line each."""
    done = []
    for pth in glob.glob(os.path.join(venv, "lib", "python3*", "site-packages", PTH_NAME)):
        os.remove(pth)
        done.append(f"removed {pth}")
    restored = 0
    for entry in os.scandir(os.path.join(venv, "bin")):
        if entry.is_symlink() or not entry.is_file():
            continue  # the python links
        with open(entry.path, "rb") as script:
            if script.read(len(HELD)) != HELD.encode():
                continue
            rest = script.read()
        with open(entry.path, "wb") as script:
            script.write(b"#!" + rest)
        restored += 1
    if restored:
        done.append(f"{restored} console scripts start Python directly again")
    return done


if __name__ == "__main__":
    for line in remove_hold(sys.argv[1]):
        print(line)
