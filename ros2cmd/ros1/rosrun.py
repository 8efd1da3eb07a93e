"""`rosrun PKG EXECUTABLE [ARGS]` (and `ros2 run ...`): start one executable of a package.

    rosrun ros_tutorials_topic topic_publisher
    rosrun beginner_tutorials talker __name:=my_talker chatter:=other
    rosrun ros_tutorials_parameter dynamics_talker _talker_str:=Goodbye

PKG and EXECUTABLE are the seeds' names, or any package of the ament index (a learner's own,
built with colcon: `source install/setup.bash` first), looked up in the package index
(ros_tutorials_common/packages.py, the one place that turns them into a command line). The
process is replaced by the executable (as ROS 1's rosrun does with `exec`), so its output,
Ctrl-C and exit status are the executable's own; it starts with this project's DDS defaults.

The ROS 1 argument forms the seeds use are translated to ROS 2's:

    __name:=NAME    ->  --ros-args -r __node:=NAME
    __ns:=/NS       ->  --ros-args -r __ns:=/NS   (a relative NS gets its leading '/')
    from:=to        ->  --ros-args -r from:=to
    _param:=value   ->  --ros-args -p param:=value   (a private parameter; '/' becomes '.')

Arguments after `--ros-args` (up to `--`) are ROS 2 arguments already and pass unchanged, as
do the program's own arguments (`rosrun ros_tutorials_service service_client 2 3`).
A name that ROS cannot take (`__name:=pub-1`) is refused in one line, before the node starts.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.run import run
from ros_tutorials_common import packages
from ros_tutorials_common.shutdown import program_main

USAGE = "usage: rosrun PKG EXECUTABLE [ARGS ...]"


@program_main
def rosrun(argv: Sequence[str] | None = None) -> int:
    """The `rosrun` command (console script)."""
    if completion.requested():  # the shell asking for TAB's completions: ends here
        completion.answer(_completion_parser())
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv[:1] in (["-h"], ["--help"]):
        print(USAGE)
        print(__doc__.split("\n", 2)[2].strip("\n"))
        return 0
    try:
        if not argv:
            raise ToolError(f"{USAGE}; packages: {packages.known_package_names()}")
        if len(argv) == 1:
            names = sorted(packages.executable_commands(argv[0]))
            if not names:
                # ROS 1's tools are packages of one executable: `rosrun rqt_graph rqt_graph`.
                # command() raises the one-line error for a tool that is not here.
                packages.command(argv[0], argv[0])
                names = [argv[0]]
            raise ToolError(f"{USAGE}; {argv[0]} has: {', '.join(names)}")
        run(argv[0], argv[1], argv[2:])
    except (ToolError, packages.UnknownExecutable) as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    return 0  # not reached: run() replaces this process


def _completion_parser() -> argparse.ArgumentParser:
    """rosrun's words, for TAB completion only (rosrun reads its arguments itself: ROS 1's
    `name:=value` forms are no options)."""
    parser = argparse.ArgumentParser(prog="rosrun")
    parser.add_argument("package_name")
    parser.add_argument("executable_name")
    parser.add_argument("args", nargs=argparse.REMAINDER)
    completion.attach(
        parser,
        package_name=completion.package_names,
        executable_name=completion.executable_names,
    )
    return parser
