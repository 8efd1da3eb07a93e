"""turtle_tf2_py, the demo of the official tf2 pages: turtle broadcasters, the listener that
makes turtle2 follow, the static, fixed and dynamic frame broadcasters, and launch/."""
