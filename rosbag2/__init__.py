"""The bag library: rosbag2's format on disk (MCAP storage, as ROS 2 Jazzy writes it).

As rosbag2's storage, storage_mcap and cpp libraries are below its Python API and its command
line, this package is below `rosbag2_py` (the API a learner's code imports) and `ros2 bag` /
`rosbag` (ros2cmd/bag/, ros2cmd/ros1/rosbag.py); it imports nothing of either. Its parts:
metadata.py (metadata.yaml), offered_qos.py (the QoS profiles in it), definitions.py (the
message definitions stored as schemas), mcap_file.py (one .mcap file, through the ``mcap``
package), writer.py, reader.py, reindex.py (repair), loss.py (what a recorder lost),
errors.py (BagError).
"""
