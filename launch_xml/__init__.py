"""launch_xml: its XMLLaunchDescriptionSource, for Python launch files that include XML."""
