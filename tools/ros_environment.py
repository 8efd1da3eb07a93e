"""Make this environment what `source /opt/ros/jazzy/setup.bash` makes a shell: the ROS 2
underlay a learner builds their own packages on.

`source .venv/bin/activate` then sets, besides the venv's own:
- ROS_VERSION, ROS_PYTHON_VERSION and ROS_DISTRO (the official tutorial "Configuring
  environment" checks them with `printenv | grep -i ROS`);
- AMENT_PREFIX_PATH naming this environment (the ament index that `ros2`, rosidl's CMake code
  and colcon read; a sourced workspace is put in front of it);
- this project's DDS defaults (ros_tutorials_common/dds.py, the one place that decides them),
  each unless the user has set it, so a node of the learner's own package, however started,
  keeps DDS on this machine;
- CMAKE_TOOLCHAIN_FILE, unless set: interfaces/cmake/colcon_toolchain.cmake, what `colcon
  build` of an ament_cmake package needs here that a ROS 2 installation would not;
- COLCON_DEFAULTS_FILE, unless set: ros_tutorials_common/config/colcon_defaults.yaml, where
  a package whose build fails is one line (ros_tutorials_common/colcon_events.py);
- PYTHONWARNINGS, unless set: pkg_resources' DeprecationWarning ignored. flake8-import-order
  0.18.2 (Ubuntu 24.04's, which ament_flake8 loads in every `colcon test` of a learner's
  package) imports pkg_resources, and setuptools 68 (Jazzy's) warns on that: `colcon test`
  would report stderr output for every package;
- in an interactive bash or zsh, TAB completion of `ros2` and the ROS 1 tools: argcomplete's
  shell code for them (ros_tutorials_common/completion.py), written once into
  share/ros-tutorials/ros2-argcomplete.bash (nothing, quietly, without argcomplete), as a ROS
  2 install's setup.bash sources ros2cli's ros2-argcomplete.bash.
The venv's activate scripts (bash/zsh, fish, csh) get one marked block each, written again
when it changed and otherwise left alone; `deactivate` (bash/zsh) takes it all away again.

The prefix also gets the files a ROS 2 install prefix has, local_setup.{sh,bash,zsh} and
setup.{sh,bash,zsh}: each activates this environment. colcon puts a prefix with such files
into the chain of the workspace's install/setup.bash, so `source install/setup.bash` in a new
terminal activates the environment it was built in first, as it sources /opt/ros/jazzy there.

    .venv/bin/python tools/ros_environment.py [--prefix DIR]
"""

from __future__ import annotations

import argparse
import re
import shlex
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
from ros_tutorials_common.completion import COMMANDS  # noqa: E402 - after ROOT is importable
from ros_tutorials_common.dds import DDS_DEFAULTS  # noqa: E402

VARIABLES = {"ROS_VERSION": "2", "ROS_PYTHON_VERSION": "3", "ROS_DISTRO": "jazzy"}
TOOLCHAIN = ROOT / "interfaces" / "cmake" / "colcon_toolchain.cmake"
COLCON_DEFAULTS = ROOT / "ros_tutorials_common" / "config" / "colcon_defaults.yaml"
BEGIN = "# >>> ros-tutorials: the ROS 2 environment (tools/ros_environment.py) >>>"
END = "# <<< ros-tutorials <<<"
SETUP_FILES = ("local_setup.sh", "local_setup.bash", "local_setup.zsh")
SETUP_FILES += tuple(name.removeprefix("local_") for name in SETUP_FILES)
PKG_RESOURCES_WARNING = "ignore:pkg_resources is deprecated as an API:DeprecationWarning"
COMPLETION = Path("share", "ros-tutorials", "ros2-argcomplete.bash")  # under the prefix


def defaults() -> dict[str, str]:
    """The variables set unless the user has set them."""
    return {
        **DDS_DEFAULTS,
        "CMAKE_TOOLCHAIN_FILE": str(TOOLCHAIN),
        "COLCON_DEFAULTS_FILE": str(COLCON_DEFAULTS),
        "PYTHONWARNINGS": PKG_RESOURCES_WARNING,
    }


def block(shell: str, prefix: Path) -> str:
    here = str(prefix)
    if shell == "fish":
        lines = [f"set -gx {name} {shlex.quote(value)}" for name, value in VARIABLES.items()]
        lines += [f"set -q {n}; or set -gx {n} {shlex.quote(v)}" for n, v in defaults().items()]
        lines.append(f"set -q AMENT_PREFIX_PATH; or set -gx AMENT_PREFIX_PATH {shlex.quote(here)}")
    elif shell == "csh":
        lines = [f"setenv {name} {shlex.quote(value)}" for name, value in VARIABLES.items()]
        lines += [f"if (! $?{n}) setenv {n} {shlex.quote(v)}" for n, v in defaults().items()]
        lines.append(f"if (! $?AMENT_PREFIX_PATH) setenv AMENT_PREFIX_PATH {shlex.quote(here)}")
    else:
        lines = [f"export {name}={value}" for name, value in VARIABLES.items()]
        # The defaults this block set (not the user's) are remembered, for deactivate.
        for name, value in defaults().items():
            lines += [
                f'if [ -z "${{{name}+x}}" ]; then',
                f"    export {name}={shlex.quote(value)}",
                f'    _ROS_TUTORIALS_SET="${{_ROS_TUTORIALS_SET-}} {name}"',
                "fi",
            ]
        # This environment is the underlay: last in AMENT_PREFIX_PATH, once.
        lines += [
            f'case ":${{AMENT_PREFIX_PATH-}}:" in *:{shlex.quote(here)}:*) ;; *)',
            '    export AMENT_PREFIX_PATH="${AMENT_PREFIX_PATH:+$AMENT_PREFIX_PATH:}"'
            f"{shlex.quote(here)};;",
            "esac",
        ]
        lines += completion_lines(prefix)
        # deactivate is a shell function of the venv's: wrap it so all this goes with it.
        names = " ".join(VARIABLES)
        remove_prefix = [
            f"_ros_tutorials_here={shlex.quote(here)}",
            '_ros_tutorials_p=":${AMENT_PREFIX_PATH-}:"',
            '_ros_tutorials_p="${_ros_tutorials_p//:$_ros_tutorials_here:/:}"',
            '_ros_tutorials_p="${_ros_tutorials_p#:}"; _ros_tutorials_p="${_ros_tutorials_p%:}"',
            'if [ -n "$_ros_tutorials_p" ]; then export AMENT_PREFIX_PATH="$_ros_tutorials_p"',
            "else unset AMENT_PREFIX_PATH; fi",
            "unset _ros_tutorials_p _ros_tutorials_here",
        ]
        lines += [
            "if typeset -f deactivate >/dev/null 2>&1",
            "then",
            '    eval "_ros_tutorials_$(typeset -f deactivate)"',
            "    deactivate () {",
            f"        unset {names} ${{_ROS_TUTORIALS_SET-}} _ROS_TUTORIALS_SET",
            f"        complete -r {' '.join(COMMANDS)} 2>/dev/null",
            *(f"        {line}" for line in remove_prefix),
            '        _ros_tutorials_deactivate "$@"',
            "    }",
            "fi",
        ]
    return "\n".join([BEGIN, *lines, END]) + "\n"


def completion_lines(prefix: Path) -> list[str]:
    """Shell lines that register TAB completion in an interactive bash or zsh (and do nothing
    where the completion script is not there)."""
    script = shlex.quote(str(prefix / COMPLETION))
    return [
        f'if [ -n "${{BASH_VERSION-}}${{ZSH_VERSION-}}" ] && [ -r {script} ]; then',
        f"    case $- in *i*) . {script} ;; esac",
        "fi",
    ]


def completion_script() -> str | None:
    """argcomplete's bash and zsh code for COMMANDS; None without argcomplete."""
    try:
        from argcomplete.shell_integration import shellcode
    except ImportError:
        return None
    return (
        "# TAB completion of ros2 and the ROS 1 tools (argcomplete), for an interactive bash or\n"
        "# zsh: sourced by the environment's activate (tools/ros_environment.py writes it).\n"
        "# zsh: its completion system first, as ros2cli's ros2-argcomplete.zsh loads it.\n"
        'if [ -n "${ZSH_VERSION-}" ] && ! type compdef >/dev/null 2>&1; then\n'
        "    autoload -U +X compinit && compinit\n"
        "fi\n" + shellcode(COMMANDS, shell="bash")
    )


def install(script: Path, shell: str, prefix: Path) -> bool:
    """Write the block into SCRIPT (replacing an older one); whether the file changed."""
    text = script.read_text()
    kept = re.sub(rf"\n?{re.escape(BEGIN)}.*?{re.escape(END)}\n", "", text, flags=re.S)
    new = kept.rstrip("\n") + "\n\n" + block(shell, prefix)
    if new == text:
        return False
    script.write_text(new)
    return True


def setup_file(prefix: Path) -> str:
    activate = shlex.quote(str(prefix / "bin" / "activate"))
    # Activated already (a shell started from an activated one): TAB completion all the same.
    again = "".join(f"    {line}\n" for line in completion_lines(prefix))
    return (
        "# This environment as a ROS 2 underlay (tools/ros_environment.py): sourcing this is\n"
        "# what sourcing /opt/ros/jazzy/setup.bash is elsewhere. A workspace built here sources\n"
        "# it first from its install/setup.bash.\n"
        f'if [ "${{VIRTUAL_ENV-}}" != {shlex.quote(str(prefix))} ]; then . {activate}\n'
        f"else\n{again}fi\n"
    )


def write_if_changed(path: Path, text: str) -> bool:
    if path.is_file() and path.read_text() == text:
        return False
    path.write_text(text)
    return True


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--prefix", type=Path, default=Path(sys.prefix), help="default: the venv")
    prefix = parser.parse_args(argv).prefix.absolute()
    for name, shell in (("activate", "sh"), ("activate.fish", "fish"), ("activate.csh", "csh")):
        script = prefix / "bin" / name
        if script.is_file() and install(script, shell, prefix):
            print(f"{script}: sets {', '.join([*VARIABLES, 'AMENT_PREFIX_PATH', *defaults()])}")
    code = completion_script()
    if code is None:
        (prefix / COMPLETION).unlink(missing_ok=True)
    else:
        (prefix / COMPLETION).parent.mkdir(parents=True, exist_ok=True)
        if write_if_changed(prefix / COMPLETION, code):
            print(f"{prefix / COMPLETION}: TAB completion of {', '.join(COMMANDS)}")
    changed = [name for name in SETUP_FILES if write_if_changed(prefix / name, setup_file(prefix))]
    if changed:
        print(f"{prefix}: {', '.join(changed)} (a ROS 2 underlay for colcon workspaces)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
