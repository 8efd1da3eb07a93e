"""Bags: record, inspect and replay topics in rosbag2's format (MCAP storage, as ROS 2 Jazzy).

The bag on disk: metadata.py (metadata.yaml), offered_qos.py (the QoS profiles in it),
mcap_file.py (one .mcap file, through the ``mcap`` package), writer.py, reader.py and
reindex.py (repair), errors.py (BagError). definitions.py makes the schemas, and record.py,
info.py, play.py are the verbs; ros2/ is their ``ros2 bag ...`` spelling,
ros2cmd/ros1/rosbag.py ROS 1's ``rosbag ...``, and options.py what both spellings share.
"""
