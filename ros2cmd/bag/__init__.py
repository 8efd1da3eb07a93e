"""Bags: record, inspect and replay topics in rosbag2's format (MCAP storage, as ROS 2 Jazzy).

storage.py reads and writes the bag (metadata.yaml + .mcap, through the ``mcap`` package),
definitions.py makes the schemas, and record.py, info.py, play.py are the verbs; cli.py
gives them both spellings, ``ros2 bag ...`` and ROS 1's ``rosbag ...``.
"""
