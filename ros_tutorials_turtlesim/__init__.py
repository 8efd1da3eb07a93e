"""turtlesim on rclpy: the simulator (turtlesim_node), turtle_teleop_key, mimic and draw_square."""
