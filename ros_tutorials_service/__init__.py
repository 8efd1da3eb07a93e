"""The service lesson: SrvTutorial server and client on ``ros_tutorial_srv``, and the
classic AddTwoInts server and client on ``add_two_ints``."""

# Started as `python -m` (ros2 run, the launcher): rclpy's shutdown race on Ctrl-C is the stop
# (docs/lesson-files.md). Here, not in the lesson files, which stay plain rclpy.
from ros_tutorials_common.lesson_scripts import take_shutdown_race_for_the_stop

take_shutdown_race_for_the_stop()
