"""What the tools and turtlesim share (the lessons are plain rclpy and use none of it, except
that the project starts them through ``lesson_scripts``), in two parts:

Here, modules that never import rclpy (the launcher uses them and stays light; a test
checks that importing any of them loads no rclpy):

- ``dds``: the one place that sets this project's DDS defaults
- ``ament``, ``packages``: the package index the launcher and the tools read (the ament
  index of AMENT_PREFIX_PATH; a package's executables as command lines)
- ``lesson_scripts``: the lessons' console scripts: the DDS defaults, then the lesson's main
- ``cli``: argument types and exit codes shared by the command-line programs
- ``bounded``: reading files, pipes and YAML from users within limits
- ``shutdown``: how every program ends on Ctrl-C, SIGTERM and output it cannot write
- ``wait``: the one wait loop (spin until something is true)
- ``drawing``: a graph drawn as rqt_graph draws it (rqt_graph, view_frames)

``ros_tutorials_common.ros``: what needs rclpy, the command line before ``rclpy.init``
(``ros_args``: DDS defaults and checked ROS arguments; ``user_args``: the program's own
arguments; ``init``, ``run_node``).
"""
