"""The launcher: runs ROS 1 (roslaunch) XML files and ROS 2 launch files in XML, YAML, Python.

    python -m launcher union.launch [name:=value ...] [--screen] [--print] [--show-args]

The work flows one way through small modules: parse (XML or YAML -> elements with file:line;
a Python file runs through python_files.py and the ``launch`` API instead),
resolve (args, conditions, substitutions, scopes -> node declarations), plan (declarations ->
process specs with full command lines, printable), supervise (start, prefix output, respawn,
shut down). ``LaunchError`` is the one error type every stage raises for bad input.
"""


class LaunchError(Exception):
    """A problem in a launch file or on the command line: reported as one line, exit code 1."""


class CodeRefused(LaunchError):
    """A launch file asks to run code ($(eval) beyond values and operators, $(command)) and
    the user did not pass --allow-code; ``what`` is the file:line and what it asks."""

    def __init__(self, what: str) -> None:
        super().__init__(f"{what}; pass --allow-code to allow it")
        self.what = what
