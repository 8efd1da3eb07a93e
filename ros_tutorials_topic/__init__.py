"""The topic lesson: a publisher and a subscriber exchanging MsgTutorial messages,
and the classic talker/listener on ``chatter``."""

# Started as `python -m` (ros2 run, the launcher): rclpy's shutdown race on Ctrl-C is the stop
# (docs/lesson-files.md). Here, not in the lesson files, which stay plain rclpy.
from ros_tutorials_common.lesson_scripts import take_shutdown_race_for_the_stop

take_shutdown_race_for_the_stop()
