"""The toolkit's one error type: a message for the user, printed as one line.

The command line (`ros2cmd.cli.execute`) prints it and exits 1; the libraries below the command
line (the bag library, tf2's tools) raise it too, so they need nothing of the command line.
"""

from __future__ import annotations


class ToolError(Exception):
    """Something the user asked for cannot be done; str(error) says why, in one line."""

    prefix = "error: "  # how cli.execute prints it: `error: unknown node '/x' ...`


class ToolFailure(ToolError):
    """A failure ros2cli reports in its own words (`Setting parameter failed: ...`): the line
    is printed as it is, without the 'error: ' prefix; the exit status is 1 all the same."""

    prefix = ""
