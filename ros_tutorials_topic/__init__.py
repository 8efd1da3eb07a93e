"""The topic lesson: a publisher and a subscriber exchanging MsgTutorial messages,
and the classic talker/listener on ``chatter``."""

from ros_tutorials_common.ctrl_c import release as _release_ctrl_c

_release_ctrl_c()  # Ctrl-C from here on ends a command quietly (see ctrl_c.py)
