"""What the tutorial nodes and tools share that is not a lesson (each lesson shows its own
steps: rclpy.init, the node, spin, shutdown, in its own file), in two parts:

Here, modules that never import rclpy (the launcher uses them and stays light; a test
checks that importing any of them loads no rclpy):

- ``dds``: the one place that sets this project's DDS defaults
- ``cli``: argument types and exit codes shared by the command-line programs
- ``int64``: keeping the servers' results inside int64
- ``bounded``: reading files, pipes and YAML from users within limits
- ``ctrl_c``: how the tools end on Ctrl-C

``ros_tutorials_common.ros``: what needs rclpy, the command line before ``rclpy.init``
(``ros_args``: DDS defaults and checked ROS arguments; ``user_args``: the program's own
arguments; ``init`` for the tools), and what the lesson clients and the action server do
besides the book's steps (``service_client_steps``, ``action_client_steps``,
``action_server_steps``).
"""
