"""The `ros2` command line (ros2cli's verbs and output), and the seeds' ROS 1 spellings of it.

    ros2 topic list              rostopic list
    ros2 topic echo /chatter     rostopic echo /chatter
    ros2 service call /ros_tutorial_srv ros_tutorials_interfaces/srv/SrvTutorial '{a: 10, b: 5}'
                                    rosservice call /ros_tutorial_srv 10 5
    ros2 param set /service_server calculation_method 2
                                    rosparam set /calculation_method 2

See `ros2 --help`; the ROS 1 front-ends are in ros1/.
"""
