"""Make `source .venv/bin/activate` set what `source /opt/ros/jazzy/setup.bash` sets for a
learner to see: ROS_VERSION, ROS_PYTHON_VERSION and ROS_DISTRO (the official tutorial
"Configuring environment" checks them with `printenv | grep -i ROS`).

The venv's activate scripts (bash/zsh, fish, csh) get one marked block each, written again
when it changed and otherwise left alone; `deactivate` (bash/zsh) unsets the three again.

    .venv/bin/python tools/ros_environment.py [--prefix DIR]
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

VARIABLES = {"ROS_VERSION": "2", "ROS_PYTHON_VERSION": "3", "ROS_DISTRO": "jazzy"}
BEGIN = "# >>> ros-tutorials: the ROS 2 environment (tools/ros_environment.py) >>>"
END = "# <<< ros-tutorials <<<"


def block(shell: str) -> str:
    if shell == "fish":
        lines = [f"set -gx {name} {value}" for name, value in VARIABLES.items()]
    elif shell == "csh":
        lines = [f"setenv {name} {value}" for name, value in VARIABLES.items()]
    else:
        lines = [f"export {name}={value}" for name, value in VARIABLES.items()]
        # deactivate is a shell function of the venv's: wrap it so the three go with it.
        names = " ".join(VARIABLES)
        lines += [
            "if typeset -f deactivate >/dev/null 2>&1",
            "then",
            '    eval "_ros_tutorials_$(typeset -f deactivate)"',
            f'    deactivate () {{ unset {names}; _ros_tutorials_deactivate "$@"; }}',
            "fi",
        ]
    return "\n".join([BEGIN, *lines, END]) + "\n"


def install(script: Path, shell: str) -> bool:
    """Write the block into SCRIPT (replacing an older one); whether the file changed."""
    text = script.read_text()
    kept = re.sub(rf"\n?{re.escape(BEGIN)}.*?{re.escape(END)}\n", "", text, flags=re.S)
    new = kept.rstrip("\n") + "\n\n" + block(shell)
    if new == text:
        return False
    script.write_text(new)
    return True


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--prefix", type=Path, default=Path(sys.prefix), help="default: the venv")
    prefix = parser.parse_args(argv).prefix
    for name, shell in (("activate", "sh"), ("activate.fish", "fish"), ("activate.csh", "csh")):
        script = prefix / "bin" / name
        if script.is_file() and install(script, shell):
            print(f"{script}: sets {', '.join(VARIABLES)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
