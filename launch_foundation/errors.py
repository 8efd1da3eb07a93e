"""The launch stack's errors: every layer (the model, the front-ends, the launcher) raises
these for bad input, and the launcher reports them as one line and exit status 1."""


class LaunchError(Exception):
    """A problem in a launch file or on the command line: reported as one line, exit code 1."""


class CodeRefused(LaunchError):
    """A launch file asks to run code ($(eval) beyond values and operators, $(command)) and
    the user did not pass --allow-code; ``what`` is the file:line and what it asks."""

    def __init__(self, what: str) -> None:
        super().__init__(f"{what}; pass --allow-code to allow it")
        self.what = what
