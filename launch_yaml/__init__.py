"""launch_yaml: its YAMLLaunchDescriptionSource, for Python launch files that include YAML."""

from ros_tutorials_common.ctrl_c import release as _release_ctrl_c

_release_ctrl_c()  # Ctrl-C from here on ends a command quietly (see ctrl_c.py)
