"""ament_copyright, this environment's own: the copyright linter that the test_copyright.py of
every package `ros2 pkg create` makes imports (`from ament_copyright.main import main`).

ROS 2 Jazzy's ament_copyright is not on PyPI. This one, written for this project, checks what
the template's test asks: each source file has a copyright notice and a licence header; one
line per file that lacks one, status 1. Its ament index entry is made by `make setup`
(tools/register_packages.py), so `rosdep` finds it as a ROS install would.
"""
