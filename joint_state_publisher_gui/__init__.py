"""joint_state_publisher_gui: joint_state_publisher with a slider per movable joint.

`ros2 run joint_state_publisher_gui joint_state_publisher_gui [URDF_FILE]` runs
joint_state_publisher_gui.py: ROS 2's window of sliders (Randomize, Center, one slider per
joint) as a page in the browser, behind the guard of this project's web tools
(ros_tutorials_web/guard.py). Not on PyPI: this project's own.
"""
