"""The XML launcher: runs ROS 1 (roslaunch) and ROS 2 launch XML files of this project.

    python -m launcher union.launch [name:=value ...] [--screen] [--print] [--show-args]

The work flows one way through small modules: parse (XML -> elements with file:line),
resolve (args, conditions, substitutions, scopes -> node declarations), plan (declarations ->
process specs with full command lines, printable), supervise (start, prefix output, respawn,
shut down). ``LaunchError`` is the one error type every stage raises for bad input.
"""


class LaunchError(Exception):
    """A problem in a launch file or on the command line: reported as one line, exit code 1."""
