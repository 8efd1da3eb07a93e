"""The one error type of the ros2 command: a message for the user, printed as one line."""


class ToolError(Exception):
    """Something the user asked for cannot be done; str(error) says why, in one line."""

    prefix = "error: "  # how cli.execute prints it: `error: unknown node '/x' ...`


class ToolFailure(ToolError):
    """A failure ros2cli reports in its own words (`Setting parameter failed: ...`): the line
    is printed as it is, without the 'error: ' prefix; the exit status is 1 all the same."""

    prefix = ""
