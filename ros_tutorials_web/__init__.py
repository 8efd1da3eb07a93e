"""The web viewer: the running ROS system in a browser (`ros2 run ros_tutorials_web viewer`)."""
