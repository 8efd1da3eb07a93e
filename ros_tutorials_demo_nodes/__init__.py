"""ROS 2's service introspection demos (ros2/demos, Jazzy): a client that asks /add_two_ints
every half second and the server that answers, each with a parameter that turns service
introspection off, to metadata, or to contents. They run under demo_nodes_cpp's and
demo_nodes_py's names (`ros2 run demo_nodes_cpp introspection_service`)."""
