"""What the tutorial nodes and tools share that is not a lesson (each lesson shows its own
steps: rclpy.init, the node, spin, shutdown, in its own file).

- ``dds``: the one place that sets this project's DDS defaults
- ``node_main``: the command line before rclpy.init (``ros_args``: DDS defaults and checked
  ROS arguments; ``user_args``: the program's own arguments; ``init`` for the tools)
- ``cli``: argument types and exit codes shared by the command-line programs
- ``int64``: keeping the servers' results inside int64

Nothing heavy is imported here, so a light user (the launcher needs only ``dds``) does not pay
for loading rclpy; ``ctrl_c`` (no rclpy) makes a Ctrl-C during a command's start quiet.
"""

from ros_tutorials_common.ctrl_c import release as _release_ctrl_c

_release_ctrl_c()  # Ctrl-C from here on ends a command quietly (see ctrl_c.py)
