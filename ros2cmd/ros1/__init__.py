"""The ROS 1 spellings the seeds type, each a thin front-end onto the ros2 code, one module per
tool: the same functions run, with ROS 1's arguments and output where ROS 1 differs.

    rostopic.py, rosservice.py, rosparam.py, rosnode.py, rosmsg.py (also rossrv)
                          the graph tools, on topic/, service/, param/ (their api.py),
                          node.py, interface/; tool.py what they share (parser,
                          no-ROS-2-meaning)
    rosrun.py             on run.py (`ros2 run`)
    rosbag.py             on bag/ (`ros2 bag`)
    rospack.py            `rospack find|list`, on the package index (`ros2 pkg prefix`)
    rqt.py                rqt_graph, rqt_console, rqt_logger_level, roslaunch-logs: on
                          graph_view/, console.py, log.py
    roscore.py            ROS 2 has no master: says what replaces it, waits for Ctrl-C
    shell.py              roscd, rosed, roscp, catkin_*, rqt, roswtf: what to type instead

`roslaunch` is the launcher's own command (`python -m launcher`, launcher/__main__.py); `ros2
launch` is the front-end onto it. Nothing here is imported by the ros2 verbs.
"""
