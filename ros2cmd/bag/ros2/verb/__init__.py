"""`ros2 bag`'s verbs, one module each: HELP, add_arguments(parser) and main(graph, args), as
ros2bag's verb/ has them (reindex is options.py's, shared with ROS 1's rosbag)."""
