"""The one error type of the ros2 command: a message for the user, printed as one line."""


class ToolError(Exception):
    """Something the user asked for cannot be done; str(error) says why, in one line."""
