"""tf2_tools: view_frames, the tree of tf2 frames being broadcast.

ros2 run tf2_tools view_frames
"""
