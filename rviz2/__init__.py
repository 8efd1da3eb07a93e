"""rviz2, the 3D view, in a browser: ``rviz2`` (rviz2.py) serves a three.js page (static/)
behind the web viewer's guard; scene.py is its ROS node, config.py reads .rviz files,
robot_model.py URDFs, encode.py turns messages into what the page draws."""
