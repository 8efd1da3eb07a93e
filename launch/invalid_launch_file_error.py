"""launch.invalid_launch_file_error: a launch file no front-end could read."""

from __future__ import annotations

from launch_foundation import LaunchError


class InvalidLaunchFileError(LaunchError):
    """A launch file of an unknown kind or that failed to load; ``likely_errors``: what each
    front-end that tried it said."""

    def __init__(self, extension: str = "", *, likely_errors: list[Exception] | None = None):
        self._extension = extension
        self._likely_errors = likely_errors
        if not likely_errors:
            kind = f"'{extension}' " if extension else ""
            message = f"The launch file may have a syntax error, or its {kind}format is unknown"
        elif len(likely_errors) == 1:
            error = likely_errors[0]
            message = (
                f"Caught exception when trying to load file of format [{extension}]: "
                f"{type(error).__name__}: {error}"
            )
        else:
            message = "Caught multiple exceptions when trying to load file of format "
            message += f"[{extension}]:\n" + "\n".join(
                f" - {type(error).__name__}: {error}" for error in likely_errors
            )
        super().__init__(message)
