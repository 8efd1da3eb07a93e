"""The service lesson: SrvTutorial server and client on ``ros_tutorial_srv``, and the
classic AddTwoInts server and client on ``add_two_ints``."""

from ros_tutorials_common.ctrl_c import release as _release_ctrl_c

_release_ctrl_c()  # Ctrl-C from here on ends a command quietly (see ctrl_c.py)
