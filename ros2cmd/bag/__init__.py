"""`ros2 bag` and `rosbag`: record, inspect and replay topics, on the bag library (rosbag2/).

record.py, info.py, play.py are the verbs' work; ros2/ is their ``ros2 bag ...`` spelling,
ros2cmd/ros1/rosbag.py ROS 1's ``rosbag ...``, options.py what both spellings share,
keyboard.py the player's keys. The bag on disk is the library's (rosbag2/), as ros2bag stands
on rosbag2_py and rosbag2_cpp.
"""
