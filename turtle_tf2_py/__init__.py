"""turtle_tf2_py, the demo of the official tf2 pages: turtle broadcasters, the listener that
makes turtle2 follow, the static, fixed and dynamic frame broadcasters, and launch/."""

# Started as `python -m` (ros2 run, the launcher): rclpy's shutdown race on Ctrl-C is the stop,
# as for the lesson packages; the node files stay plain rclpy.
from ros_tutorials_common.lesson_scripts import take_shutdown_race_for_the_stop

take_shutdown_race_for_the_stop()
