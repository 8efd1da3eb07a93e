"""The launcher as launch.LaunchService's runner: LaunchDescriptions a script built, executed by
the model into a plan, planned and supervised as ``ros2 launch`` runs a file.

``launch`` does not import the tool above it: it finds this function through the
``launch.runner`` entry point (pyproject.toml), as ros2/launch finds its front-ends.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from launch_foundation.errors import LaunchError


def run(
    descriptions: Iterable[Any],
    launch_configurations: dict[str, str],
    argv: list[str] | None,
    debug: bool,
    started: Callable[[], None],
    executed: Callable[[Any], None] | None = None,
) -> int:
    """Execute ``descriptions`` in one launch, then supervise its processes until it ends;
    ``executed`` gets the launch's context once they executed (what they set), ``started`` is
    called once the processes are about to start. The exit code: 0, 1 after an error (one
    line on stderr), 130 after Ctrl-C."""
    from launch.launch_context import LaunchContext
    from launcher import plan, supervise
    from launcher.loading import Loader
    from launcher.scope import Options, Scope

    try:
        loader = Loader(Options(allow_code=True))
        root = Scope(loader, Path("<LaunchService>"), "ros2", {}, {})
        root.args.update(launch_configurations)
        context = LaunchContext(root, loader.plan, loader.launch_state(), argv=argv)
        for description in descriptions:
            context.visit(description)
        launch = loader.finish()
        if executed is not None:
            executed(context)
        specs = plan.make_plan(launch)
        log_dir = supervise.make_log_dir()
    except LaunchError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    runner = supervise.Supervisor(
        specs, log_dir, debug, launch.steps, True, launch.warnings, launch.messages
    )
    started()
    return runner.run()
