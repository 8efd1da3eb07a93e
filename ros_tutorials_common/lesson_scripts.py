"""The lessons' console scripts (``topic_publisher``, ``service_client 2 3``, ...): this
project's DDS defaults (after the environment check `ros2 run` makes), then the lesson's own
``main()``.

A lesson file is plain rclpy and sets no defaults: the environment it starts in does
(``source .venv/bin/activate``, ``ros2 run``, rosrun and the launcher apply ``dds.py``'s).
A console script typed without activating the environment (``.venv/bin/topic_publisher``)
gets them here: pyproject.toml's [project.scripts] points each lesson's script at this
module's attribute of the same name, ``ros_tutorials_common.lesson_scripts:topic_publisher``,
which applies the defaults and calls ``ros_tutorials_topic.publisher.main()``. The package
index (ros_tutorials_common/packages.py) runs the lesson module itself.

Here too, not in the lessons: rclpy's shutdown race on Ctrl-C (docs/lesson-files.md).
"""

from __future__ import annotations

import importlib
from collections.abc import Callable

from ros_tutorials_common.dds import apply_dds_defaults, environment_problem

SHUT_DOWN_WHILE_PUBLISHING = "publisher's context is invalid"

# Console script -> the lesson module whose main() it runs.
LESSONS = {
    "topic_publisher": "ros_tutorials_topic.publisher",
    "topic_subscriber": "ros_tutorials_topic.subscriber",
    "talker": "ros_tutorials_topic.talker",
    "listener": "ros_tutorials_topic.listener",
    "aandb_talker": "ros_tutorials_topic.aandb_talker",
    "aandb_listener": "ros_tutorials_topic.aandb_listener",
    "num_publisher": "ros_tutorials_topic.num_publisher",
    "num_subscriber": "ros_tutorials_topic.num_subscriber",
    "user_record_publisher": "ros_tutorials_topic.user_record_publisher",
    "user_record_subscriber": "ros_tutorials_topic.user_record_subscriber",
    "service_server": "ros_tutorials_service.server",
    "service_client": "ros_tutorials_service.client",
    "add_two_ints_server": "ros_tutorials_service.add_two_ints_server",
    "add_two_ints_client": "ros_tutorials_service.add_two_ints_client",
    "service_server_with_parameter": "ros_tutorials_parameter.server",
    "service_client_with_parameter": "ros_tutorials_parameter.client",
    "dynamics_talker": "ros_tutorials_parameter.talker",
    "action_server": "ros_tutorials_action.server",
    "action_client": "ros_tutorials_action.client",
    "introspection_service": "ros_tutorials_demo_nodes.introspection_service",
    "introspection_client": "ros_tutorials_demo_nodes.introspection_client",
    "introspection": "ros_tutorials_demo_nodes.introspection",
}


def __getattr__(name: str) -> Callable[[], int | None]:
    """The console script ``name`` (``from ros_tutorials_common.lesson_scripts import talker``,
    as the script pip writes reads)."""
    if name not in LESSONS:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

    def run_lesson() -> int | None:
        problem = environment_problem()  # as `ros2 run` checks: rclpy.init would fail
        if problem:
            raise SystemExit(f"error: {problem}")
        apply_dds_defaults()  # before the lesson's rclpy.init, which is when DDS reads them
        try:
            return importlib.import_module(LESSONS[name]).main()
        except RuntimeError as error:
            # rclpy's race: its Ctrl-C/SIGTERM handler shut ROS down in its own thread while a
            # timer published (RCLError "publisher's context is invalid"). That is the stop.
            if SHUT_DOWN_WHILE_PUBLISHING not in str(error):
                raise
            return 0

    return run_lesson
