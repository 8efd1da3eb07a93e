"""rostool: the ROS 2 command-line introspection tools, and their ROS 1 spellings.

    rostool topic list              rostopic list
    rostool topic echo /chatter     rostopic echo /chatter
    rostool service call /ros_tutorial_srv ros_tutorials_interfaces/srv/SrvTutorial '{a: 10, b: 5}'
                                    rosservice call /ros_tutorial_srv 10 5
    rostool param set /service_server calculation_method 2
                                    rosparam set /calculation_method 2

See `rostool --help`; the ROS 1 front-ends are in ros1.py.
"""

from ros_tutorials_common.ctrl_c import release as _release_ctrl_c

_release_ctrl_c()  # Ctrl-C from here on ends a command quietly (see ctrl_c.py)
