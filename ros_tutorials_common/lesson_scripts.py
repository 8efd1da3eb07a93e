"""The lessons' console scripts (``topic_publisher``, ``service_client 2 3``, ...): this
project's DDS defaults (after the environment check `ros2 run` makes), then the lesson's own
``main()``.

A lesson file is plain rclpy and sets no defaults: the environment it starts in does
(``source .venv/bin/activate``, ``ros2 run``, rosrun and the launcher apply ``dds.py``'s).
A console script typed without activating the environment (``.venv/bin/topic_publisher``)
gets them here. pyproject.toml's [project.scripts] is the one place a lesson's script is named:
its value names the lesson module after this module,
``ros_tutorials_common.lesson_scripts:ros_tutorials_topic.publisher``, and the script pip
writes runs ``from ros_tutorials_common.lesson_scripts import ros_tutorials_topic`` then
``ros_tutorials_topic.publisher()``: the defaults, then ``ros_tutorials_topic.publisher.main()``.
The lesson is imported by the name the script gives, after the defaults, so nothing here
imports a lesson package (the lessons sit above this floor). The package index
(ros_tutorials_common/packages.py, ``lesson_module``) reads the same values.

Here too, not in the lessons: rclpy's shutdown race on Ctrl-C (docs/lesson-files.md).
"""

from __future__ import annotations

import importlib
import os
import sys
from collections.abc import Callable
from typing import Any

from ros_tutorials_common.dds import apply_dds_defaults, environment_problem

# rclpy's race on Ctrl-C/SIGTERM: its signal handler shuts ROS down in its own thread, and a
# timer's publish, or the spin's next wait, then fails on the shut-down context (RCLError
# "publisher's context is invalid", "the given context is not valid"). That is the stop.
SHUT_DOWN_CONTEXT = ("context is invalid", "context is not valid")


def is_shutdown_race(error: BaseException) -> bool:
    return isinstance(error, RuntimeError) and any(m in str(error) for m in SHUT_DOWN_CONTEXT)


def take_shutdown_race_for_the_stop() -> None:
    """For a lesson started as ``python -m PKG.MODULE`` (ros2 run, rosrun, the launcher): the
    race above ends the process with status 0 and no traceback, as the console scripts' run()
    does. Called by the lesson packages' __init__, which such a start imports first (a lesson
    file stays plain rclpy); only while Python is locating a -m module."""
    if sys.argv[:1] != ["-m"]:
        return
    previous, previous_unraisable = sys.excepthook, sys.unraisablehook

    def hook(kind: type[BaseException], error: BaseException, trace: Any) -> None:
        if not is_shutdown_race(error):
            previous(kind, error, trace)
            return
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(0)

    def unraisable(what: Any) -> None:
        # The Ctrl-C landed in a __del__ (rclpy's Future's), where Python only prints it:
        # rclpy's handler has shut ROS down all the same, which ends the spin (hook above).
        if not isinstance(what.exc_value, KeyboardInterrupt):
            previous_unraisable(what)

    sys.excepthook, sys.unraisablehook = hook, unraisable


# The packages whose modules a script may name (the lessons and the demo nodes).
LESSON_PACKAGE_PREFIX = "ros_tutorials_"


def lesson_module(script_value: str) -> str | None:
    """The lesson module a console script's ``module:attr`` value runs, or None if it is not
    a lesson's script."""
    module, _, attribute = script_value.partition(":")
    if module.strip() != __name__:
        return None
    return attribute.strip()


def run(module: str) -> int | None:
    """Check the environment, apply the DDS defaults, then run ``module``'s main()."""
    problem = environment_problem()  # as `ros2 run` checks: rclpy.init would fail
    if problem:
        raise SystemExit(f"error: {problem}")
    apply_dds_defaults()  # before the lesson's rclpy.init, which is when DDS reads them
    try:
        return importlib.import_module(module).main()
    except RuntimeError as error:
        if not is_shutdown_race(error):
            raise
        return 0


class _Package:
    """``ros_tutorials_topic`` as a script's first name: its attributes are the lessons' runs."""

    def __init__(self, name: str) -> None:
        self.name = name

    def __getattr__(self, module: str) -> Callable[[], int | None]:
        if module.startswith("__"):
            raise AttributeError(module)
        return lambda: run(f"{self.name}.{module}")


def __getattr__(name: str) -> _Package:
    """The first name of a lesson script's value (``... import ros_tutorials_topic``)."""
    if not name.startswith(LESSON_PACKAGE_PREFIX):
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return _Package(name)
