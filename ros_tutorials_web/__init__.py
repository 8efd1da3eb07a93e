"""The web viewer: the running ROS system in a browser (`ros2 run ros_tutorials_web viewer`)."""

from ros_tutorials_common.ctrl_c import release as _release_ctrl_c

_release_ctrl_c()  # Ctrl-C from here on ends a command quietly (see ctrl_c.py)
