"""The parameter lesson: a service server whose operator is the parameter
``calculation_method``, its client, and a talker whose text is the parameter ``talker_str``."""

from ros_tutorials_common.ctrl_c import release as _release_ctrl_c

_release_ctrl_c()  # Ctrl-C from here on ends a command quietly (see ctrl_c.py)
