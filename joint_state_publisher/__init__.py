"""joint_state_publisher: a value for every movable joint of a robot, on /joint_states.

`ros2 run joint_state_publisher joint_state_publisher [URDF_FILE]` runs the node of
joint_state_publisher.py, as ROS 2 Jazzy's (names, parameters, topics). Not on PyPI: this
project's own. joint_state_publisher_gui moves the same joints with sliders.
"""
