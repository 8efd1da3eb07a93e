"""robot_state_publisher: a robot's URDF and joint positions published as tf2 frames.

`ros2 run robot_state_publisher robot_state_publisher --ros-args -p robot_description:=...`
runs the node of robot_state_publisher.py, as ROS 2 Jazzy's C++ node behaves (names,
parameters, topics, messages). Not on PyPI: this project's own.
"""
