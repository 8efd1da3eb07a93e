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
from collections.abc import Callable

from ros_tutorials_common.dds import apply_dds_defaults, environment_problem

SHUT_DOWN_WHILE_PUBLISHING = "publisher's context is invalid"
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
        # rclpy's race: its Ctrl-C/SIGTERM handler shut ROS down in its own thread while a
        # timer published (RCLError "publisher's context is invalid"). That is the stop.
        if SHUT_DOWN_WHILE_PUBLISHING not in str(error):
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
